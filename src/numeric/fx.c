/* fx.c - the fixed layer's one variable, the saturation count (fx.h),
 * and the partial products out of line where FX_MUL64_PARTIAL = 2 asks
 * for them (fx_wide.h). The operations are in fx_div.c, fx_root.c and
 * fx_setup.c. */
#include "fx.h"

#if FX_COUNT_SATURATIONS
volatile uint32_t fx_saturations;
#endif

#if FX_MUL64_PARTIAL == 2
int64_t fx_mul64_call(int32_t a, int32_t b) { return fx_mul64_parts(a, b); }
uint64_t fx_umul64_call(uint32_t a, uint32_t b) { return fx_umul64_parts(a, b); }
#endif
