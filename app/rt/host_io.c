/* host_io.c - file input and error reporting shared by the hosted tools. */
#include "host_io.h"

#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *host_read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "%s: cannot open: %s\n", path, strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap + 1);
    const char *why = buf ? NULL : "out of memory";
    while (buf) {
        if (n == cap) {
            char *nb = realloc(buf, (cap *= 2) + 1);
            if (!nb) {
                why = "out of memory";
                break;
            }
            buf = nb;
        }
        errno = 0;
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0) {
            if (ferror(f))
                why = strerror(errno ? errno : EIO);
            break;
        }
    }
    fclose(f);
    if (why) {
        fprintf(stderr, "%s: cannot read: %s\n", path, why);
        free(buf);
        return NULL;
    }
    buf[n] = '\0';
    *len = n;
    return buf;
}

void host_error_at(const char *path, unsigned line, const char *msg)
{
    if (line)
        fprintf(stderr, "%s:%u: %s\n", path, line, msg);
    else
        fprintf(stderr, "%s: %s\n", path, msg);
}

int host_usage_error(const char *prog, const char *help, const char *fmt, const char *arg)
{
    fprintf(stderr, "%s: ", prog);
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n(run '%s' for usage)\n", help);
    return EXIT_BAD_INPUT;
}

int host_option_error(const char *prog, const char *help, int c, char *const *argv,
                      const host_option_need_t *needs)
{
    /* the option as written: the argument getopt_long just stepped over */
    const char *arg = argv[optind - 1];
    char name[64];
    if (strncmp(arg, "--", 2) == 0) {
        size_t n = strcspn(arg, "=");
        snprintf(name, sizeof name, "%.*s", (int)(n < sizeof name ? n : sizeof name - 1), arg);
    } else {
        snprintf(name, sizeof name, "-%c", optopt);
    }
    if (c == ':') {
        const char *what = "a value";
        for (; needs && needs->what; needs++)
            if (needs->val == optopt)
                what = needs->what;
        char msg[160];
        snprintf(msg, sizeof msg, "%s needs %s", name, what);
        return host_usage_error(prog, help, "%s", msg);
    }
    /* glibc sets optopt to the value of a long option given a value it
     * does not take */
    if (optopt != 0 && strncmp(arg, "--", 2) == 0 && strchr(arg, '='))
        return host_usage_error(prog, help, "option '%s' takes no value", arg);
    return host_usage_error(prog, help, "unknown option '%s'", name);
}
