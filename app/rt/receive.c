/*
 * receive.c - `rt receive [STREAM] -o OUT.png`: decode the framed stream
 * that the board's UART sink writes (uart_stream.c), print the report
 * lines on stdout and write the image. STREAM is a file, a pipe or FIFO,
 * or a serial line (put into raw mode for the run; set its speed with
 * stty first); stdin by default. With --report-only the stream holds
 * report lines and no frame (a board that draws on its own panel): they
 * are printed and no image is written.
 *
 * It returns once the frame has ended and the report lines after it are
 * in: to the end of a regular file, or until a live input (pipe, FIFO,
 * serial line) stays idle for --report-wait milliseconds. Exit status 2
 * on a missing, truncated or corrupt frame: never a partial image.
 */
#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include "host_io.h"
#include "image.h"
#include "receive.h"
#include "uart_stream.h"
#include "rt_version.h"

static const char receive_usage[] =
    "usage: rt receive [STREAM] -o OUT.png [options]\n"
    "       rt receive [STREAM] --report-only [options]\n"
    "\n"
    "Decodes the board's framed UART stream (a file, a pipe, a serial line such\n"
    "as /dev/ttyUSB0, or stdin when STREAM is missing or '-'), prints its report\n"
    "lines on stdout and writes the frame as OUT.png or OUT.ppm. Bytes before\n"
    "the frame header (boot text, noise) are skipped; it returns at the end of\n"
    "the frame and the report lines after it.\n"
    "  -o, --output FILE      output image (.png or .ppm)\n"
    "  --report-only          the stream holds report lines and no frame (a board\n"
    "                         that draws on its own panel): print them, write no\n"
    "                         image; bytes before the first line are skipped,\n"
    "                         after it only whole report lines may follow\n"
    "  --report-wait MS       on a pipe or serial line, the report after the frame\n"
    "                         (--report-only: after a report line) ends when\n"
    "                         nothing arrives for MS ms (default 500)\n"
    "  -h, --help             this text; --version: the version\n"
    "\n"
    "exit status: 0 success, 1 output failure, 2 no frame, a truncated or corrupt\n"
    "frame (no image is written), or bad usage; with --report-only 0 when at\n"
    "least one report line was read, 2 for none, a truncated or damaged line,\n"
    "anything else after one, or a frame in the stream\n";

#define RECEIVE_HELP "rt receive --help"

enum { OPT_REPORT_WAIT = 256, OPT_REPORT_ONLY, OPT_VERSION };

static const struct option receive_options[] = {
    { "output", required_argument, NULL, 'o' },
    { "report-wait", required_argument, NULL, OPT_REPORT_WAIT },
    { "report-only", no_argument, NULL, OPT_REPORT_ONLY },
    { "help", no_argument, NULL, 'h' },
    { "version", no_argument, NULL, OPT_VERSION },
    { NULL, 0, NULL, 0 },
};

static const host_option_need_t receive_needs[] = {
    { 'o', "a file name" }, { OPT_REPORT_WAIT, "a number of milliseconds" }, { 0, NULL },
};

typedef struct {
    int fd;
    bool live;   /* not a regular file: may go idle instead of ending */
    int wait_ms; /* idle time that ends the report after the frame */
} fd_source_t;

static long fd_read(void *ctx, uint8_t *buf, size_t cap, bool after_frame)
{
    fd_source_t *s = ctx;
    if (after_frame && s->live) {
        struct pollfd p = { .fd = s->fd, .events = POLLIN };
        int n;
        do
            n = poll(&p, 1, s->wait_ms);
        while (n < 0 && errno == EINTR);
        if (n <= 0)
            return n; /* idle: the report is over (or poll failed) */
    }
    ssize_t n;
    do
        n = read(s->fd, buf, cap);
    while (n < 0 && errno == EINTR);
    return (long)n;
}

static void print_text(void *ctx, const char *text, size_t len)
{
    (void)ctx;
    printf("%.*s\n", (int)len, text);
    fflush(stdout); /* a live report shows as it comes */
}

/* Raw 8-bit input on a serial line: no line editing, echo, CR/LF
 * translation or flow-control characters eaten. The speed is kept. */
static bool make_raw(int fd, struct termios *saved)
{
    if (tcgetattr(fd, saved) != 0)
        return false;
    struct termios t = *saved;
    t.c_iflag &= ~(tcflag_t)(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL | IXON | IXOFF);
    t.c_oflag &= ~(tcflag_t)OPOST;
    t.c_lflag &= ~(tcflag_t)(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
    t.c_cflag &= ~(tcflag_t)(CSIZE | PARENB);
    t.c_cflag |= CS8 | CREAD | CLOCAL;
    t.c_cc[VMIN] = 1;
    t.c_cc[VTIME] = 0;
    return tcsetattr(fd, TCSANOW, &t) == 0;
}

int cmd_receive(int argc, char **argv)
{
    const char *in_path = NULL, *out_path = NULL;
    bool report_only = false;
    long wait_ms = 500;
    opterr = 0;
    int c;
    while ((c = getopt_long(argc, argv, ":ho:", receive_options, NULL)) != -1) {
        switch (c) {
        case 'o':
            out_path = optarg;
            break;
        case OPT_REPORT_ONLY:
            report_only = true;
            break;
        case OPT_REPORT_WAIT: {
            char *end;
            errno = 0;
            wait_ms = strtol(optarg, &end, 10);
            if (errno || end == optarg || *end || wait_ms < 0 || wait_ms > 600000)
                return host_usage_error("rt receive", RECEIVE_HELP,
                                        "--report-wait: expected 0..600000 milliseconds, got '%s'", optarg);
            break;
        }
        case 'h':
            fputs(receive_usage, stdout);
            return 0;
        case OPT_VERSION:
            printf("rt %s\n", RT_VERSION_STRING);
            return 0;
        default:
            return host_option_error("rt receive", RECEIVE_HELP, c, argv, receive_needs);
        }
    }
    if (argc - optind > 1)
        return host_usage_error("rt receive", RECEIVE_HELP, "unexpected argument '%s'", argv[optind + 1]);
    if (argc - optind == 1 && strcmp(argv[optind], "-") != 0)
        in_path = argv[optind];
    if (report_only && out_path)
        return host_usage_error("rt receive", RECEIVE_HELP, "%s", "--report-only writes no image: drop -o");
    if (!out_path && !report_only)
        return host_usage_error("rt receive", RECEIVE_HELP, "%s", "no output file given (-o OUT.png)");
    char why[256];
    if (out_path && image_check_output(out_path, why, sizeof why) != 0) {
        fprintf(stderr, "rt receive: %s\n", why);
        return 1;
    }

    const char *name = in_path ? in_path : "stdin";
    fd_source_t src = { .fd = 0, .wait_ms = (int)wait_ms };
    if (in_path && (src.fd = open(in_path, O_RDONLY | O_NOCTTY)) < 0) {
        fprintf(stderr, "rt receive: %s: cannot open: %s\n", in_path, strerror(errno));
        return EXIT_BAD_INPUT;
    }
    struct stat st;
    src.live = fstat(src.fd, &st) != 0 || !S_ISREG(st.st_mode);
    struct termios saved;
    bool raw = isatty(src.fd) && make_raw(src.fd, &saved);

    rx_source_t rx = { .read = fd_read, .text = print_text, .ctx = &src };
    rx_result_t res;
    int rc = report_only ? rx_reports(&rx, &res) : rx_frame(&rx, &res);
    if (raw)
        tcsetattr(src.fd, TCSANOW, &saved);
    if (in_path)
        close(src.fd);
    if (rc != 0) {
        fprintf(stderr, "rt receive: %s: %s\n", name, res.error);
        /* bytes but no header: most often the board sent its frame header
         * before rt receive was listening, and the rest was skipped */
        if (res.no_header && res.offset > 0)
            fprintf(stderr,
                    "rt receive: %s: hint: %lu report line(s) and %lu other byte(s) but no frame header: start "
                    "rt receive (or the capture) before resetting or powering the board, so that it reads the "
                    "frame from its start\n",
                    name, res.texts, res.skipped);
        return EXIT_BAD_INPUT;
    }
    if (res.skipped)
        fprintf(stderr, "rt receive: %s: note: skipped %lu byte(s) before the %s\n", name, res.skipped,
                report_only ? "first report line" : "frame header");
    if (report_only)
        return 0;
    rc = 0;
    if (image_write(out_path, &res.img, why, sizeof why) != 0) {
        fprintf(stderr, "rt receive: %s\n", why);
        rc = 1;
    }
    image_free(&res.img);
    return rc;
}
