/* fn.h: compiled user functions (`function { ... }`) and the small stack
 * machine that evaluates them. The front end compiles; isosurfaces,
 * patterns and the parser's own calls evaluate, millions of times, with no
 * allocation. */
#ifndef LUCENT_FN_H
#define LUCENT_FN_H

#include <signal.h>
#include <stdbool.h>
#include <stdint.h>

enum fn_op {
	FN_CONST,    /* push k */
	FN_ARG,      /* push args[i] */
	FN_ADD, FN_SUB, FN_MUL, FN_DIV, FN_NEG, FN_NOT,
	FN_LT, FN_LE, FN_EQ, FN_GE, FN_GT, FN_NE, FN_AND, FN_OR,
	FN_CALL1,    /* replace top with f1(top) */
	FN_CALL2,    /* pop b, a; push f2(a, b) */
	FN_MIN,      /* pop i values, push the least */
	FN_MAX,
	FN_SELECT,   /* pop i (3 or 4) values: select(a, b, c [, d]) */
	FN_USER,     /* pop i values, push fn(values) */
	FN_INTERNAL, /* pop i values, push internal function #k(values) */
	FN_SUM,      /* pop hi, lo; push the sum of fn(args..., v) for v = lo..hi */
	FN_PROD,     /* the same, multiplied */
	FN_JZ,       /* pop; if zero, jump to instruction i */
	FN_JMP,      /* jump to instruction i */
	FN_PATTERN,  /* pop z, y, x; push the value of pattern pat at (x, y, z) */
	FN_PIGMENT,  /* pop z, y, x; push component i (0..4 red..transmit, 5 gray) of pigment pig there */
	FN_VECTOR,   /* pop fn's nparams values; push component i (0..4, 5 gray) of the
	              * vector- or colour-valued function fn at them */
};

struct fn;
struct pattern;
struct pigment;

struct fn_instr {
	uint8_t op;
	int32_t i;                   /* argument index, count or jump target */
	double k;                    /* constant */
	union {
		double (*f1)(double);
		double (*f2)(double, double);
		const struct fn *fn;     /* FN_USER: a reference held by the owner */
		const struct pattern *pat; /* FN_PATTERN: held by the function that owns it */
		const struct pigment *pig; /* FN_PIGMENT: the same */
	};
};

enum { FN_MAX_PARAMS = 32, FN_MAX_STACK = 256 };

struct fn {
	int refs;
	int nparams;
	struct fn_instr *code;
	int ncode, cap;
	int depth;                   /* the deepest stack the code reaches */
	struct fn **callees;         /* functions it calls, one reference each */
	int ncallees;
	struct pattern *pat;         /* function { pattern { } }: owned */
	struct pigment *pig;         /* function { pigment { } }: one reference; the
	                              * function is colour-valued (fn_eval_color) */
	/* function { spline { } } and function { transform { } }: a
	 * vector-valued function whose evaluator the front end supplies.
	 * vdata is owned, released by vfree. */
	int vdim;                    /* components of the result (2..5); 0: not vector-valued */
	void (*veval)(const void *vdata, const double *args, double out[5]);
	void (*vfree)(void *vdata);
	void *vdata;
};

struct fn *fn_new(int nparams);
struct fn *fn_ref(struct fn *f);
void fn_unref(struct fn *f);
/* Append an instruction; returns its index. */
int fn_emit(struct fn *f, struct fn_instr in);
/* Evaluate f with args[0..nparams). A colour- or vector-valued function
 * gives its first component. */
double fn_eval(const struct fn *f, const double *args);
/* The flag a signal handler sets to stop the program (main's Ctrl-C):
 * sum() and prod() loops, which may run for as long as their bounds say,
 * leave off when it is set, and the parser or renderer then stops at its
 * next check. NULL (the default): never stopped. */
void fn_set_stop(volatile sig_atomic_t *stop);
/* A bound on the terms of one sum() or prod(), which then leave off (the
 * fuzz harnesses set it, as they bound a scene's directives: a sum over
 * 1e90 terms is the user's to stop, not a bug). Default: none. */
void fn_set_max_terms(double n);
/* A colour-valued function's colour at args (x, y, z): red, green, blue,
 * filter, transmit. */
void fn_eval_color(const struct fn *f, const double *args, double out[5]);
/* The components of f at args: a colour-valued function's colour, a
 * vector-valued function's vector (zeros past f->vdim), or a float
 * function's value in out[0] and zeros. */
void fn_eval_vector(const struct fn *f, const double *args, double out[5]);
/* A function with a value of several components (a colour or a vector)? */
static inline bool fn_is_vector(const struct fn *f)
{
	return f->pig || f->vdim > 0;
}
/* An internal function of POV-Ray's numbering (function { internal(N) }):
 * its value at args (nargs values), or NaN if N is unknown. */
double fn_internal(int n, const double *args, int nargs);
/* How many parameters internal function N takes, or -1 if there is none. */
int fn_internal_params(int n);

#endif
