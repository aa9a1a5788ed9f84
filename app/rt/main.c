/*
 * main.c - the hosted `rt` command: render an NFF scene to PNG/PPM with the
 * fixed or the double build of the core, or compare two images.
 */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "backend.h"
#include "bands.h"
#include "host_io.h"
#include "image.h"
#include "receive.h"
#include "report.h"
#include "rt_version.h"

static const char usage_text[] =
    "usage: rt [options] SCENE.nff -o OUT.png|OUT.ppm\n"
    "       rt compare A.png B.png [--psnr-min DB] [--max-over8 PERCENT] [--max-error N] [--blur SIGMA]\n"
    "       rt receive [STREAM] -o OUT.png   (the board's UART stream, stdin by default)\n"
    "       rt receive [STREAM] --report-only   (its report lines alone: a board with a panel)\n"
    "       rt --version\n"
    "\n"
    "render options:\n"
    "  -o, --output FILE   output image; the format follows the extension\n"
    "  --size WxH          image size (default: the scene's resolution)\n"
    "%s" /* the backends */
    "  --depth N           maximum ray-tree depth, 1..%d (default %d)\n"
    "  --viewport X,Y,W,H  render only that rectangle of the frame; the output\n"
    "                      image is the rectangle (pixels as in the whole frame)\n"
    "  --format F          framebuffer pixel format: %s\n"
    "                      (the first is the default; written expanded to RGB)\n"
    "  --dither            ordered dithering (4x4 Bayer) of the formats with fewer\n"
    "                      than 8 bits a channel and of l8's luma\n"
    "  --stats[=FORMAT]    print the render's counters (the board report's keys),\n"
    "                      BVH shape and render time on stderr: 'key value' lines\n"
    "                      (text, the default) or one JSON object (json)\n"
    "  --spd               SPD test procedure: 512x512 pixels (or --size) from corner\n"
    "                      rays, four averaged per pixel, depth 5, SPD rule 8\n"
    "  --aa L[,T]          adaptive anti-aliasing: split a pixel's square where its\n"
    "                      corners differ by more than T/255 (default %d), at most\n"
    "                      L times (1..%d)\n"
    "  --spp N             uniform anti-aliasing: N x N samples a pixel (2..%d;\n"
    "                      --double --spp 16 is the converged pixel-area image)\n"
    "  --same-samples B    with --aa: trace exactly the samples build B (fixed,\n"
    "                      float, ...) would, by replaying its split decisions\n"
    "                      (B renders first, in memory): --double --aa 3\n"
    "                      --same-samples fixed is the exact model at the fixed\n"
    "                      build's (the board's) samples. Without --aa every\n"
    "                      build's samples are the same already\n"
    "  --texture-filter on|off\n"
    "                      textures averaged over each pixel's footprint (on, the\n"
    "                      default) or sampled at the hit point (off: the model\n"
    "                      of the pixel-area image, --double --spp 16 --texture-filter off)\n"
    "  --adaptive W        skip child rays whose share of the pixel is below W\n"
    "                      (0.001..1; off by default)\n"
    "  --threads N         render with N threads, 1..%d (default: the online CPUs,\n"
    "                      here %u); the image is the same for every N\n"
    "  --progressive       render in 7 interlaced passes, as a panel shows them\n"
    "                      (one thread; the image is the scanline order's)\n"
    "  --progressive-pass N\n"
    "                      the picture as it stands after pass N (1..7): each\n"
    "                      pixel the one traced at the corner of its cell\n"
    "  --quiet             no progress indicator\n"
    "  -h, --help          this text; --version: the version\n"
    "Options take their value as the next argument or after '='\n"
    "(--size=64x64); '--' ends the options. 'rt compare --help' and\n"
    "'rt receive --help' describe the other commands.\n"
    "\n"
    "exit status: 0 success, 1 output or threshold failure, 2 bad input or usage\n";

static const char compare_usage[] =
    "usage: rt compare A B [options]   (PNG or binary PPM images of the same size)\n"
    "\n"
    "Prints PSNR, the largest channel difference and the share of pixels off by\n"
    "more than 2/255 and 8/255.\n"
    "  --psnr-min DB       exit 1 if PSNR is below DB\n"
    "  --max-over8 PCT     exit 1 if more than PCT % of pixels differ by > 8/255\n"
    "  --max-error N       exit 1 if any channel differs by more than N/255\n"
    "  --blur SIGMA        first blur both images by a Gaussian of SIGMA pixels\n"
    "                      (0..16; how an eye sees a small panel: for dithering)\n"
    "  -h, --help          this text; --version: the version\n"
    "\n"
    "exit status: 0 within the thresholds, 1 over one, 2 bad input or usage\n";

static bool parse_uint(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end != '\0' || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

static bool parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end != '\0' || v != v)
        return false;
    *out = v;
    return true;
}

/* How many fraction bits the geometry gave up so that a far camera or
 * light fits the range (the reader puts the largest coordinate of the
 * geometry in [8, 16) otherwise). */
static int geometry_bits_lost(const rt_backend_t *be)
{
    double mn[3], mx[3], m = 0;
    if (!be->bounds(mn, mx))
        return 0;
    for (int k = 0; k < 3; k++)
        m = fmax(m, fmax(fabs(mn[k]), fabs(mx[k])));
    double scaled = ldexp(m, (int)be->scale_log2());
    int lost = scaled > 0 ? 3 - (int)floor(log2(scaled)) : 0;
    return lost > 0 ? lost : 0;
}

/* The backends, from the one list (backend.h), in its order. */
#define BACKEND_INDEX(id, name, what) BACKEND_INDEX_##id,
enum { RT_HOST_BACKENDS(BACKEND_INDEX) };
#undef BACKEND_INDEX
static const struct {
    const char *name, *what;
    const rt_backend_t *be;
} backends[] = {
#define BACKEND_ROW(id, name, what) { name, what, &rt_backend_##id },
    RT_HOST_BACKENDS(BACKEND_ROW)
#undef BACKEND_ROW
};
#define N_BACKENDS (sizeof backends / sizeof backends[0])

static const char *backend_name(const rt_backend_t *be)
{
    for (size_t i = 0; i < N_BACKENDS; i++)
        if (backends[i].be == be)
            return backends[i].name;
    return "?";
}

/* The pixel formats, from the one list (rt_fb.h). */
static const struct {
    const char *name;
    rt_fb_format_t format;
} formats[] = {
#define FORMAT_ROW(id, name, value, bits) { name, id },
    RT_FB_FORMATS(FORMAT_ROW)
#undef FORMAT_ROW
};
#define FORMAT_NAMES_(id, name, value, bits) name " "
static const char format_list[] = RT_FB_FORMATS(FORMAT_NAMES_);
#undef FORMAT_NAMES_

static void print_usage(void)
{
    char lines[1024] = "";
    size_t used = 0;
    for (size_t i = 0; i < N_BACKENDS && used < sizeof lines; i++)
        used += (size_t)snprintf(lines + used, sizeof lines - used, "  --%-17s %s\n", backends[i].name,
                                 backends[i].what);
    printf(usage_text, lines, RT_MAX_DEPTH, RT_DEFAULT_DEPTH, format_list, RT_AA_THRESHOLD, RT_AA_MAX_LEVELS, RT_AA_MAX_SPP,
           RT_MAX_WORKERS, bands_default_threads());
}

enum {
    OPT_SIZE = 256, OPT_VIEWPORT, OPT_DEPTH, OPT_FORMAT, OPT_DITHER, OPT_STATS, OPT_SPD, OPT_AA, OPT_SPP, OPT_SAME_SAMPLES, OPT_TEXTURE_FILTER, OPT_ADAPTIVE, OPT_THREADS, OPT_PROGRESSIVE, OPT_PROGRESSIVE_PASS, OPT_QUIET, OPT_VERSION,
    OPT_PSNR_MIN, OPT_MAX_OVER8, OPT_MAX_ERROR, OPT_BLUR,
    OPT_BACKEND /* + the backend's index */
};

static const struct option render_options[] = {
    { "output", required_argument, NULL, 'o' },
    { "size", required_argument, NULL, OPT_SIZE },
    { "viewport", required_argument, NULL, OPT_VIEWPORT },
#define BACKEND_OPTION(id, name, what) { name, no_argument, NULL, OPT_BACKEND + BACKEND_INDEX_##id },
    RT_HOST_BACKENDS(BACKEND_OPTION)
#undef BACKEND_OPTION
    { "depth", required_argument, NULL, OPT_DEPTH },
    { "format", required_argument, NULL, OPT_FORMAT },
    { "dither", no_argument, NULL, OPT_DITHER },
    { "stats", optional_argument, NULL, OPT_STATS },
    { "spd", no_argument, NULL, OPT_SPD },
    { "aa", required_argument, NULL, OPT_AA },
    { "spp", required_argument, NULL, OPT_SPP },
    { "same-samples", required_argument, NULL, OPT_SAME_SAMPLES },
    { "texture-filter", required_argument, NULL, OPT_TEXTURE_FILTER },
    { "adaptive", required_argument, NULL, OPT_ADAPTIVE },
    { "threads", required_argument, NULL, OPT_THREADS },
    { "progressive", no_argument, NULL, OPT_PROGRESSIVE },
    { "progressive-pass", required_argument, NULL, OPT_PROGRESSIVE_PASS },
    { "quiet", no_argument, NULL, OPT_QUIET },
    { "help", no_argument, NULL, 'h' },
    { "version", no_argument, NULL, OPT_VERSION },
    { NULL, 0, NULL, 0 },
};

static const host_option_need_t render_needs[] = {
    { 'o', "a file name" }, { OPT_SIZE, "WxH" }, { OPT_VIEWPORT, "X,Y,W,H" }, { OPT_DEPTH, "a number" },
    { OPT_FORMAT, "a pixel format name" }, { OPT_ADAPTIVE, "a number" },
    { OPT_AA, "LEVELS[,THRESHOLD]" }, { OPT_SPP, "a number" }, { OPT_SAME_SAMPLES, "a build name" }, { OPT_TEXTURE_FILTER, "on or off" },
    { OPT_THREADS, "a number" }, { OPT_PROGRESSIVE_PASS, "a number" }, { 0, NULL },
};

#define RENDER_HELP "rt --help"

#define TEXT_OF_(x) #x
#define TEXT_OF(x) TEXT_OF_(x)
#define DEPTH_MAX_TEXT TEXT_OF(RT_MAX_DEPTH)

static int render_usage_error(const char *fmt, const char *arg)
{
    return host_usage_error("rt", RENDER_HELP, fmt, arg);
}

/* arg as a count 1..hi: 0 with *out set, or the usage error for --name */
static int count_arg(const char *name, const char *arg, long hi, unsigned *out)
{
    long n;
    if (parse_uint(arg, 1, hi, &n)) {
        *out = (unsigned)n;
        return 0;
    }
    char msg[96];
    snprintf(msg, sizeof msg, "--%s: expected a number from 1 to %ld, got '%%s'", name, hi);
    return render_usage_error(msg, arg);
}

static int print_version(void)
{
    printf("rt %s\n", RT_VERSION_STRING);
    return 0;
}

/* --same-samples: build `from` (its scene loaded) renders *opts in memory,
 * the image dropped, recording its adaptive split decisions into
 * *splits (allocated here, the caller frees it); *opts then replays
 * them. 0, or as bands_render. */
static int take_splits(const rt_backend_t *from, rt_render_opts_t *opts, rt_fb_format_t format, unsigned threads,
                       bool progress, uint32_t **splits, rt_error_t *err)
{
    uint16_t w = opts->width, h = opts->height, sw, sh;
    from->resolution(&sw, &sh);
    size_t words = RT_AA_SPLITS_WORDS(w ? w : sw, h ? h : sh, opts->aa_levels);
    *splits = calloc(words ? words : 1, sizeof **splits);
    if (!*splits)
        return 1; /* out of memory: as a sink's failure */
    rt_render_opts_t rec = *opts;
    rec.aa_splits_mode = RT_AA_SPLITS_RECORD;
    rec.aa_splits = *splits;
    rec.aa_splits_words = words;
    image_t img;
    rt_stats_t st = { 0 };
    bands_time_t time = { 0, 0, 0 };
    int status = bands_render(from, &rec, format, false, threads, 0, progress, &img, &st, &time, err);
    if (status != 0)
        return status;
    image_free(&img);
    opts->aa_splits_mode = RT_AA_SPLITS_REPLAY;
    opts->aa_splits = *splits;
    opts->aa_splits_words = words;
    return 0;
}

static int cmd_render(int argc, char **argv)
{
    const char *scene_path = NULL, *out_path = NULL;
    const rt_backend_t *be = backends[0].be;
    const rt_backend_t *samples_be = NULL; /* --same-samples */
    rt_render_opts_t opts = { 0 };
    rt_fb_format_t format = RT_FB_RGB888;
    bool dither = false;
    bool quiet = false;
    unsigned threads = bands_default_threads();
    unsigned upto_pass = 0; /* --progressive-pass */
    bool stats = false;
    report_format_t stats_format = REPORT_TEXT;

    opterr = 0;
    int c, usage;
    while ((c = getopt_long(argc, argv, ":ho:", render_options, NULL)) != -1) {
        switch (c) {
        case 'o':
            out_path = optarg;
            break;
        case OPT_SIZE: {
            long w, h;
            char buf[32];
            const char *x = strchr(optarg, 'x');
            if (!x || (size_t)(x - optarg) >= sizeof buf)
                return render_usage_error("--size: expected WxH, got '%s'", optarg);
            memcpy(buf, optarg, (size_t)(x - optarg));
            buf[x - optarg] = '\0';
            if (!parse_uint(buf, 1, RT_MAX_WIDTH, &w) || !parse_uint(x + 1, 1, RT_MAX_HEIGHT, &h))
                return render_usage_error("--size: expected WxH from 1x1 to " TEXT_OF(RT_MAX_WIDTH) "x" TEXT_OF(
                                              RT_MAX_HEIGHT) " (RT_MAX_WIDTH x RT_MAX_HEIGHT), got '%s'",
                                          optarg);
            opts.width = (uint16_t)w;
            opts.height = (uint16_t)h;
            break;
        }
        case OPT_VIEWPORT: {
            long v[4];
            char buf[64];
            if (strlen(optarg) >= sizeof buf)
                return render_usage_error("--viewport: expected X,Y,W,H, got '%s'", optarg);
            strcpy(buf, optarg);
            char *save = NULL, *tok = strtok_r(buf, ",", &save);
            int n = 0;
            for (; tok && n < 4; tok = strtok_r(NULL, ",", &save), n++)
                if (!parse_uint(tok, n < 2 ? 0 : 1, 65535, &v[n]))
                    break;
            if (n != 4 || tok)
                return render_usage_error("--viewport: expected X,Y,W,H (W, H >= 1), got '%s'", optarg);
            opts.viewport = (rt_viewport_t){ (uint16_t)v[0], (uint16_t)v[1], (uint16_t)v[2], (uint16_t)v[3] };
            break;
        }
        case OPT_DEPTH: {
            long d;
            if (!parse_uint(optarg, 1, RT_MAX_DEPTH, &d))
                return render_usage_error("--depth: expected 1.." DEPTH_MAX_TEXT " (RT_MAX_DEPTH: a deeper tree needs "
                                          "a build with -DRT_MAX_DEPTH=N), got '%s'", optarg);
            opts.max_depth = (uint8_t)d;
            break;
        }
        case OPT_FORMAT: {
            size_t i = 0;
            while (i < sizeof formats / sizeof formats[0] && strcmp(optarg, formats[i].name) != 0)
                i++;
            if (i == sizeof formats / sizeof formats[0]) {
                char msg[160];
                snprintf(msg, sizeof msg, "--format: expected one of: %sgot '%%s'", format_list);
                return render_usage_error(msg, optarg);
            }
            format = formats[i].format;
            break;
        }
        case OPT_DITHER:
            dither = true;
            break;
        case OPT_STATS:
            if (optarg && !strcmp(optarg, "json"))
                stats_format = REPORT_JSON;
            else if (optarg && strcmp(optarg, "text") != 0)
                return render_usage_error("--stats: expected --stats, --stats=text or --stats=json, got '%s'", optarg);
            stats = true;
            break;
        case OPT_SPD:
            opts.spd = true;
            break;
        case OPT_AA: {
            long l, t = 0;
            char buf[32];
            const char *comma = strchr(optarg, ',');
            size_t n = comma ? (size_t)(comma - optarg) : strlen(optarg);
            bool ok = n < sizeof buf;
            if (ok) {
                memcpy(buf, optarg, n);
                buf[n] = '\0';
                ok = parse_uint(buf, 1, RT_AA_MAX_LEVELS, &l) && (!comma || parse_uint(comma + 1, 1, 255, &t));
            }
            if (!ok) {
                char msg[128];
                snprintf(msg, sizeof msg, "--aa: expected LEVELS (1..%d) or LEVELS,THRESHOLD (1..255), got '%%s'",
                         RT_AA_MAX_LEVELS);
                return render_usage_error(msg, optarg);
            }
            opts.aa_levels = (uint8_t)l;
            opts.aa_threshold = (uint8_t)t;
            break;
        }
        case OPT_SPP: {
            unsigned n;
            if ((usage = count_arg("spp", optarg, RT_AA_MAX_SPP, &n)) != 0)
                return usage;
            opts.spp = (uint8_t)n;
            break;
        }
        case OPT_SAME_SAMPLES: {
            size_t i = 0;
            while (i < N_BACKENDS && strcmp(optarg, backends[i].name) != 0)
                i++;
            if (i == N_BACKENDS) {
                char msg[160] = "--same-samples: expected a build (";
                for (size_t k = 0; k < N_BACKENDS; k++)
                    snprintf(msg + strlen(msg), sizeof msg - strlen(msg), "%s%s", k ? ", " : "", backends[k].name);
                snprintf(msg + strlen(msg), sizeof msg - strlen(msg), "), got '%%s'");
                return render_usage_error(msg, optarg);
            }
            samples_be = backends[i].be;
            break;
        }
        case OPT_TEXTURE_FILTER:
            if (strcmp(optarg, "on") != 0 && strcmp(optarg, "off") != 0)
                return render_usage_error("--texture-filter: expected on or off, got '%s'", optarg);
            opts.point_textures = !strcmp(optarg, "off");
            break;
        case OPT_ADAPTIVE: {
            double v;
            if (!parse_double(optarg, &v) || v < 0.001 || v > 1)
                return render_usage_error("--adaptive: expected a number from 0.001 to 1, got '%s'", optarg);
            opts.adaptive_milli = (uint16_t)(v * 1000 + 0.5);
            break;
        }
        case OPT_THREADS:
            if ((usage = count_arg("threads", optarg, RT_MAX_WORKERS, &threads)) != 0)
                return usage;
            break;
        case OPT_PROGRESSIVE:
            opts.progressive = RT_PROGRESSIVE_ALL;
            break;
        case OPT_PROGRESSIVE_PASS:
            if ((usage = count_arg("progressive-pass", optarg, RT_PROGRESSIVE_PASSES, &upto_pass)) != 0)
                return usage;
            break;
        case OPT_QUIET:
            quiet = true;
            break;
        case 'h':
            print_usage();
            return 0;
        case OPT_VERSION:
            return print_version();
        default:
            if (c >= OPT_BACKEND && c < OPT_BACKEND + (int)N_BACKENDS) {
                be = backends[c - OPT_BACKEND].be;
                break;
            }
            return host_option_error("rt", RENDER_HELP, c, argv, render_needs);
        }
    }
    for (int i = optind; i < argc; i++) {
        if (scene_path)
            return render_usage_error("unexpected argument '%s'", argv[i]);
        scene_path = argv[i];
    }
    if (!scene_path)
        return render_usage_error("%s", "no scene file given");
    if (!out_path)
        return render_usage_error("%s", "no output file given (-o OUT.png)");
    /* a wrong name or folder is reported now, not after the render */
    char why[256];
    if (image_check_output(out_path, why, sizeof why) != 0) {
        fprintf(stderr, "rt: %s\n", why);
        return 1;
    }

    size_t len;
    char *text = host_read_file(scene_path, &len);
    if (!text)
        return EXIT_BAD_INPUT;
    rt_error_t err;
    bool ok = be->load(text, len, &err);
    /* --same-samples: only adaptive anti-aliasing decides where to sample */
    bool replay = samples_be && opts.aa_levels;
    bool ok_samples = !ok || !replay || samples_be == be || samples_be->load(text, len, &err);
    free(text);
    if (!ok || !ok_samples) {
        char msg[sizeof err.msg + 64];
        snprintf(msg, sizeof msg, "%s%s%s", ok ? "the " : "", ok ? backend_name(samples_be) : "",
                 ok ? " build (--same-samples): " : "");
        strncat(msg, err.msg, sizeof msg - strlen(msg) - 1);
        host_error_at(scene_path, (unsigned)err.line, msg);
        return EXIT_BAD_INPUT;
    }

    if (be->flat_skipped())
        fprintf(stderr, "%s: note: skipped %u zero-area polygon(s)\n", scene_path,
                (unsigned)be->flat_skipped());
    int lost = geometry_bits_lost(be);
    if (be == &rt_backend_fixed && lost >= 4)
        fprintf(stderr, "%s: warning: the camera or a light lies so far beyond the geometry that the fixed "
                        "build keeps %d fewer bits for it: expect noisy edges (keep them within 500 times "
                        "the geometry's extent)\n",
                scene_path, lost);

    if (opts.spd && !opts.width) {
        opts.width = opts.height = 512;
    }
    /* the frame in bands on `threads` threads, even one: the same path
     * for every N (bands.c) */
    bool progress = !quiet && isatty(2);
    image_t img;
    rt_stats_t st = { 0 };
    bands_time_t time = { 0, 0, 0 };
    uint32_t *splits = NULL;
    int status = replay ? take_splits(samples_be, &opts, format, threads, progress, &splits, &err) : 0;
    if (status != 0) {
        if (progress)
            fprintf(stderr, "\r                \r");
        fprintf(stderr, "%s: the %s build (--same-samples): %s\n", scene_path, backend_name(samples_be),
                status < 0 ? err.msg : "framebuffer sink failed");
        free(splits);
        return status < 0 ? EXIT_BAD_INPUT : 1;
    }
    status = bands_render(be, &opts, format, dither, threads, upto_pass, progress, &img, &st, &time, &err);
    free(splits);
    if (progress)
        fprintf(stderr, "\r                \r");
    if (status != 0) {
        fprintf(stderr, "%s: %s\n", scene_path, status < 0 ? err.msg : "framebuffer sink failed");
        return status < 0 ? EXIT_BAD_INPUT : 1;
    }
    if (stats)
        report_stats(stderr, stats_format, be, backend_name(be), &st, img.width, img.height, time.wall, time.threads,
                     time.threads ? time.busy / (time.threads * time.wall) : 0, geometry_bits_lost(be));
    if (image_write(out_path, &img, why, sizeof why) != 0) {
        fprintf(stderr, "rt: %s\n", why);
        image_free(&img);
        return 1;
    }
    image_free(&img);
    return 0;
}

static const struct option compare_options[] = {
    { "psnr-min", required_argument, NULL, OPT_PSNR_MIN },
    { "max-over8", required_argument, NULL, OPT_MAX_OVER8 },
    { "max-error", required_argument, NULL, OPT_MAX_ERROR },
    { "blur", required_argument, NULL, OPT_BLUR },
    { "help", no_argument, NULL, 'h' },
    { "version", no_argument, NULL, OPT_VERSION },
    { NULL, 0, NULL, 0 },
};

static const host_option_need_t compare_needs[] = {
    { OPT_PSNR_MIN, "a non-negative number" }, { OPT_MAX_OVER8, "a non-negative number" },
    { OPT_MAX_ERROR, "a non-negative number" }, { OPT_BLUR, "a number of pixels" }, { 0, NULL },
};

#define COMPARE_HELP "rt compare --help"

/* argv[0] is "compare" */
static int cmd_compare(int argc, char **argv)
{
    const char *paths[2] = { NULL, NULL };
    double psnr_min = -1, max_over8 = -1, max_error = -1, blur = 0;
    opterr = 0;
    int c, which = 0;
    while ((c = getopt_long(argc, argv, ":h", compare_options, &which)) != -1) {
        double v;
        switch (c) {
        case OPT_PSNR_MIN:
        case OPT_MAX_OVER8:
        case OPT_MAX_ERROR:
        case OPT_BLUR:
            if (!parse_double(optarg, &v) || v < 0 || (c == OPT_BLUR && v > 16)) {
                char msg[160];
                snprintf(msg, sizeof msg, "--%s needs a %s, got '%s'", compare_options[which].name,
                         c == OPT_BLUR ? "number from 0 to 16" : "non-negative number", optarg);
                return host_usage_error("rt", COMPARE_HELP, "%s", msg);
            }
            *(c == OPT_PSNR_MIN ? &psnr_min : c == OPT_MAX_OVER8 ? &max_over8 : c == OPT_BLUR ? &blur : &max_error) = v;
            break;
        case 'h':
            fputs(compare_usage, stdout);
            return 0;
        case OPT_VERSION:
            return print_version();
        default:
            return host_option_error("rt", COMPARE_HELP, c, argv, compare_needs);
        }
    }
    if (argc - optind != 2)
        return host_usage_error("rt", COMPARE_HELP, "%s", "compare needs two image files");
    paths[0] = argv[optind];
    paths[1] = argv[optind + 1];
    image_t img[2] = { { 0, 0, NULL }, { 0, 0, NULL } };
    char why[256];
    for (int k = 0; k < 2; k++) {
        if (image_read(paths[k], &img[k], why, sizeof why) != 0) {
            fprintf(stderr, "rt: %s\n", why);
            image_free(&img[0]);
            return EXIT_BAD_INPUT;
        }
    }
    image_diff_t d;
    int rc = image_compare(&img[0], &img[1], blur, &d, why, sizeof why);
    image_free(&img[0]);
    image_free(&img[1]);
    if (rc != 0) {
        fprintf(stderr, "rt: %s, %s: %s\n", paths[0], paths[1], why);
        return EXIT_BAD_INPUT;
    }
    printf("psnr %.2f dB  max-error %d  over2 %.3f%%  over8 %.3f%%\n", d.psnr_db, d.max_err,
           100 * d.share_over2, 100 * d.share_over8);
    bool fail = (psnr_min >= 0 && d.psnr_db < psnr_min) ||
                (max_over8 >= 0 && 100 * d.share_over8 > max_over8) ||
                (max_error >= 0 && d.max_err > max_error);
    return fail ? 1 : 0;
}

int main(int argc, char **argv)
{
    /* a subcommand parses the arguments after its name */
    if (argc >= 2 && !strcmp(argv[1], "compare"))
        return cmd_compare(argc - 1, argv + 1);
    if (argc >= 2 && !strcmp(argv[1], "receive"))
        return cmd_receive(argc - 1, argv + 1);
    return cmd_render(argc, argv);
}
