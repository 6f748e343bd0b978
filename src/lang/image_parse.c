/* image_parse.c: the image blocks of image_map, bump_map, image_pattern
 * and material_map. IN PROGRESS: being written. */
#include "lang/parser.h"

void parse_image_mapping(struct parser *p, struct image_mapping *m)
{
	(void)m;
	parse_expected(p, "an image file");
}
