/* ustr.h: the characters of a string value.
 *
 * POV-Ray's strings are sequences of 16-bit character codes; lucent's are
 * C strings where a character is one of
 *   - a byte below 0x80: that ASCII code;
 *   - a byte 0x80..0xFE: a non-ASCII byte as the scene file had it (what
 *     it means depends on the global charset: text objects decode it);
 *   - 0xFF and three bytes 10xxxxxx holding a code 0x80..0xFFFF (4 + 6 +
 *     6 bits): a character given by its code, a \uNNNN escape or chr(N),
 *     which POV-Ray keeps whatever the charset.
 * A raw 0xFF in a file is read as the code 0xFF, so 0xFF always begins a
 * coded character. strlen, substr, asc and strcmp count characters. */
#ifndef LUCENT_USTR_H
#define LUCENT_USTR_H

#include <stddef.h>
#include <stdint.h>

enum { USTR_CODED = 0xFF, USTR_MAX = 0xFFFF };

/* Write character `code` (1..USTR_MAX) at out; returns its bytes (1 or 4). */
static inline size_t ustr_put(char *out, uint32_t code)
{
	if (code < 0x80) {
		out[0] = (char)code;
		return 1;
	}
	out[0] = (char)USTR_CODED;
	out[1] = (char)(0x80 | ((code >> 12) & 0x0F));
	out[2] = (char)(0x80 | ((code >> 6) & 0x3F));
	out[3] = (char)(0x80 | (code & 0x3F));
	return 4;
}

/* The code of the character at s (not at its end) and, in *len, its bytes. */
static inline uint32_t ustr_get(const char *s, size_t *len)
{
	const unsigned char *u = (const unsigned char *)s;
	if (u[0] == USTR_CODED && (u[1] & 0xC0) == 0x80 && (u[2] & 0xC0) == 0x80 && (u[3] & 0xC0) == 0x80) {
		*len = 4;
		return (uint32_t)(u[1] & 0x0F) << 12 | (uint32_t)(u[2] & 0x3F) << 6 | (u[3] & 0x3F);
	}
	*len = 1;
	return u[0];
}

/* Whether the character at s is given by its code (USTR_CODED form). */
static inline int ustr_is_coded(const char *s)
{
	size_t n;
	ustr_get(s, &n);
	return n == 4;
}

/* The number of characters of s. */
static inline size_t ustr_len(const char *s)
{
	size_t n = 0, l;
	while (*s) {
		ustr_get(s, &l);
		s += l;
		n++;
	}
	return n;
}

/* The byte offset of character i of s (its length if i is past the end). */
static inline size_t ustr_offset(const char *s, size_t i)
{
	size_t off = 0, l;
	while (i > 0 && s[off]) {
		ustr_get(s + off, &l);
		off += l;
		i--;
	}
	return off;
}

/* s as POV-Ray writes a string (#debug, #warning, #error, #write): each
 * character that is not ASCII becomes one space (measured: "\u00e9" and
 * "\u0416" both print " "). out has room for strlen(s) + 1 bytes. */
static inline void ustr_to_ascii(const char *s, char *out)
{
	size_t l;
	while (*s) {
		*out++ = (unsigned char)*s < 0x80 ? *s : ' ';
		ustr_get(s, &l);
		s += l;
	}
	*out = 0;
}

#endif
