/* noise_table.h: the measured tables behind POV-Ray's solid noise
 * (noise_table.c), private to noise.c. */
#ifndef LUCENT_PATTERN_NOISE_TABLE_H
#define LUCENT_PATTERN_NOISE_TABLE_H

#define NOISE_HASH_SIZE 4096
#define NOISE_RTABLE_SIZE 267

/* Generator 3 (noise3_gen.py): its hash table, the offset its hash adds
 * to x, and its gradients. */
#define NOISE3_SIZE 2048
#define NOISE3_X0 1599

extern const unsigned short noise_hash[NOISE_HASH_SIZE];
extern const double noise_rtable[NOISE_RTABLE_SIZE];
extern const unsigned short noise3_hash[NOISE3_SIZE];
extern const double noise3_grad[NOISE3_SIZE][3];

#endif
