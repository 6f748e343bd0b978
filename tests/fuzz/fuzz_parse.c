/* fuzz_parse.c: libFuzzer harness over the front end (lexer, parser and
 * evaluator): the input is scene text; nothing is rendered. */
#define FUZZ_RENDER 0
#include "fuzz_common.h"
