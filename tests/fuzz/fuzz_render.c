/* fuzz_render.c: libFuzzer harness that parses the input scene, then
 * prepares and renders it at 8x6 (one thread, antialiased); the image is
 * never written. */
#define FUZZ_RENDER 1
#include "fuzz_common.h"
