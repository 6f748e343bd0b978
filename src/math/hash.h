/* hash.h: deterministic random numbers. Every random number lucent draws is
 * a hash of (pixel, sample index, purpose), never a shared generator's next
 * value, so images are bit-identical whatever the thread count or tile
 * order. */
#ifndef LUCENT_HASH_H
#define LUCENT_HASH_H

#include <stdint.h>

/* A 64-bit finaliser (splitmix64's): well mixed, cheap, stateless. */
static inline uint64_t hash_mix(uint64_t z)
{
	z += 0x9e3779b97f4a7c15ull;
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}

/* A uniform double in [0, 1) from (x, y, sample, purpose). */
static inline double hash_uniform(uint32_t x, uint32_t y, uint32_t sample, uint32_t purpose)
{
	uint64_t h = hash_mix(((uint64_t)x << 32) ^ y);
	h = hash_mix(h ^ (((uint64_t)sample << 32) | purpose));
	return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

#endif
