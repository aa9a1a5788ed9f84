/* rt_error.c - message building for rt_error_t. */
#include "rt_error.h"

void rt_error_set(rt_error_t *e, uint32_t line, const char *text)
{
    e->line = line;
    e->msg[0] = '\0';
    rt_error_append(e, text);
}

void rt_error_append(rt_error_t *e, const char *text)
{
    unsigned n = 0;
    while (n < RT_ERROR_MSG_MAX - 1 && e->msg[n] != '\0')
        n++;
    while (n < RT_ERROR_MSG_MAX - 1 && *text != '\0')
        e->msg[n++] = *text++;
    e->msg[n] = '\0';
}

void rt_error_append_int(rt_error_t *e, int32_t v)
{
    char buf[12];
    unsigned i = sizeof buf;
    uint32_t u = v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
    buf[--i] = '\0';
    do {
        buf[--i] = (char)('0' + u % 10);
        u /= 10;
    } while (u != 0);
    if (v < 0)
        buf[--i] = '-';
    rt_error_append(e, &buf[i]);
}
