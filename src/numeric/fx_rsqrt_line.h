/*
 * fx_rsqrt_line.h - the seed of the reciprocal square root (fx.c): for x
 * in [2^30, 2^32), 48 lines under 2^31 / sqrt(x / 2^30), one per 2^26 of
 * x. Entry i is line i's value at the start of its interval, whose low 11
 * bits are its drop per unit of x's bits 25..10. tests/unit/test_fx.c holds
 * every line under the function and within 2^-11.4 of it.
 */
#ifndef FX_RSQRT_LINE_H
#define FX_RSQRT_LINE_H

#define FX_RSQRT_LINES 48
#define FX_RSQRT_LINE_INIT { \
        0x7FF4DBD3u, 0x7C23FB80u, 0x78A59338u, 0x756EA2FAu, 0x72761AC3u, 0x6FB47A92u, \
        0x6D237A67u, 0x6ABDC240u, 0x687ECA1Du, 0x6662A1FEu, 0x6465E1E1u, 0x6285B1C7u, \
        0x60BF69AFu, 0x5F10D19Au, 0x5D77F186u, 0x5BF2F973u, 0x5A806162u, 0x591EC953u, \
        0x57CCD944u, 0x56898936u, 0x5553C12Au, 0x542AA11Eu, 0x530D5113u, 0x51FB0909u, \
        0x50F318FFu, 0x4FF4D8F6u, 0x4EFFC0EDu, 0x4E1340E5u, 0x4D2EE0DDu, 0x4C5220D6u, \
        0x4B7CA0CFu, 0x4AADF8C9u, 0x49E5D0C3u, 0x4923D0BDu, 0x4867A8B7u, 0x47B110B2u, \
        0x46FFC0ADu, 0x465380A8u, 0x45AC08A3u, 0x4509289Fu, 0x446AB09Bu, 0x43D06097u, \
        0x433A1893u, 0x42A7A08Fu, 0x4218D88Cu, 0x418D9888u, 0x4105B885u, 0x40811882u, \
}

#endif
