// expect: 1:1: includes nested too deeply (more than 100 levels; lucent --limit include-depth=N raises it)
// expect-file: inc/self.inc
// The include nesting limit: a file that includes itself.
#include "inc/self.inc"
