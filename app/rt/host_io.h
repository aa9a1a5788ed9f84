/* host_io.h - file input and error reporting shared by the hosted tools
 * (rt, rt-scenec), so every tool says the same thing the same way. */
#ifndef HOST_IO_H
#define HOST_IO_H

#include <stddef.h>

/* The whole file, with a NUL after the last byte (not counted in *len);
 * free() it. On failure prints "path: cannot open|read: reason" on stderr
 * and returns NULL. */
char *host_read_file(const char *path, size_t *len);

/* Prints "path:line: msg" on stderr, or "path: msg" when line is 0
 * (the form of every input error, so editors can jump to it). */
void host_error_at(const char *path, unsigned line, const char *msg);

/* Exit status for bad input or usage, the same in every tool. */
#define EXIT_BAD_INPUT 2

/* Prints "prog: " + fmt (with arg) and "(run 'help' for usage)" on stderr;
 * returns EXIT_BAD_INPUT. */
int host_usage_error(const char *prog, const char *help, const char *fmt, const char *arg);

/* What an option's value is, for "--depth needs a number". */
typedef struct {
    int val; /* the option's getopt_long value */
    const char *what;
} host_option_need_t;

/* getopt_long's error c ('?' unknown or ambiguous, ':' value missing; call
 * it with opterr = 0 and an optstring starting with ':') reported through
 * host_usage_error. needs ends with { 0, NULL }. */
int host_option_error(const char *prog, const char *help, int c, char *const *argv,
                      const host_option_need_t *needs);

#endif
