/* rt_error.h - an error with the input line it refers to, built without libc. */
#ifndef RT_ERROR_H
#define RT_ERROR_H

#include <stdint.h>

#define RT_ERROR_MSG_MAX 160

typedef struct {
    uint32_t line;              /* 1-based input line, 0 when not about input */
    char msg[RT_ERROR_MSG_MAX]; /* NUL-terminated, no file name, no newline */
} rt_error_t;

/* Start the message; the append calls truncate silently at the buffer end. */
void rt_error_set(rt_error_t *e, uint32_t line, const char *text);
void rt_error_append(rt_error_t *e, const char *text);
void rt_error_append_int(rt_error_t *e, int32_t v);

#endif
