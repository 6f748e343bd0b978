/* noise_table.h: the measured tables behind POV-Ray's solid noise
 * (noise_table.c), private to noise.c. */
#ifndef LUCENT_PATTERN_NOISE_TABLE_H
#define LUCENT_PATTERN_NOISE_TABLE_H

#define NOISE_HASH_SIZE 4096
#define NOISE_RTABLE_SIZE 267

extern const unsigned short noise_hash[NOISE_HASH_SIZE];
extern const double noise_rtable[NOISE_RTABLE_SIZE];

#endif
