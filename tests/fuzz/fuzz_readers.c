/*
 * fuzz_readers.c - differential libFuzzer harness over the scene reader:
 * the fixed, float and double builds of the core read the same input and
 * must give one verdict. A scene is accepted by all three (with the same
 * scale and resolution) or rejected by all three with the same
 * "line: message", degenerate shapes and views included (the reader
 * decides them on the position grid, docs/scenes.md). Built from the
 * three backends' objects (app/rt/backend.h) at the host
 * capacities, like rt.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "backend.h"

static const rt_backend_t *const backends[] = { &rt_backend_fixed, &rt_backend_float, &rt_backend_double };
static const char *const names[] = { "fixed", "float", "double" };
#define N_BACKENDS (sizeof backends / sizeof backends[0])

static void differ(const char *what, const bool ok[], const rt_error_t err[])
{
    fprintf(stderr, "fuzz_readers: the builds differ (%s):\n", what);
    for (size_t i = 0; i < N_BACKENDS; i++)
        fprintf(stderr, "  %-6s %s %u: %s\n", names[i], ok[i] ? "accepts" : "rejects", (unsigned)err[i].line,
                ok[i] ? "" : err[i].msg);
    abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    bool ok[N_BACKENDS];
    rt_error_t err[N_BACKENDS];
    for (size_t i = 0; i < N_BACKENDS; i++) {
        memset(&err[i], 0, sizeof err[i]);
        ok[i] = backends[i]->load((const char *)data, size, &err[i]);
    }
    for (size_t i = 1; i < N_BACKENDS; i++) {
        if (ok[i] != ok[0])
            differ("verdict", ok, err);
        if (!ok[0] && (err[i].line != err[0].line || strcmp(err[i].msg, err[0].msg) != 0))
            differ("message", ok, err);
        if (ok[0]) {
            uint16_t w0, h0, w, h;
            backends[0]->resolution(&w0, &h0);
            backends[i]->resolution(&w, &h);
            if (backends[i]->scale_log2() != backends[0]->scale_log2() || w != w0 || h != h0)
                differ("scale or resolution", ok, err);
        }
    }
    return 0;
}
