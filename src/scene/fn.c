/* fn.c: the user-function stack machine (see fn.h). */
#include "scene/fn.h"

#include "scene/texture.h"

#include <math.h>
#include <stdlib.h>

struct fn *fn_new(int nparams)
{
	struct fn *f = calloc(1, sizeof *f);
	if (!f) abort();
	f->refs = 1;
	f->nparams = nparams;
	return f;
}

struct fn *fn_ref(struct fn *f)
{
	if (f)
		f->refs++;
	return f;
}

void fn_unref(struct fn *f)
{
	if (!f || --f->refs > 0)
		return;
	for (int i = 0; i < f->ncallees; i++)
		fn_unref(f->callees[i]);
	free(f->callees);
	free(f->code);
	if (f->pat) {
		pattern_clear(f->pat);
		free(f->pat);
	}
	pigment_unref(f->pig);
	if (f->vfree)
		f->vfree(f->vdata);
	free(f);
}

int fn_emit(struct fn *f, struct fn_instr in)
{
	if (f->ncode == f->cap) {
		f->cap = f->cap ? f->cap * 2 : 16;
		f->code = realloc(f->code, (size_t)f->cap * sizeof *f->code);
		if (!f->code) abort();
	}
	f->code[f->ncode] = in;
	return f->ncode++;
}

static volatile sig_atomic_t *fn_stop;
static double fn_max_terms = INFINITY;

void fn_set_stop(volatile sig_atomic_t *stop)
{
	fn_stop = stop;
}

void fn_set_max_terms(double n)
{
	fn_max_terms = n;
}

double fn_eval(const struct fn *f, const double *args)
{
	if (f->vdim > 0) {
		double v[5];
		f->veval(f->vdata, args, v);
		return v[0];
	}
	double st[FN_MAX_STACK];
	int sp = 0;
	const struct fn_instr *code = f->code;
	for (int pc = 0; pc < f->ncode; pc++) {
		const struct fn_instr *in = &code[pc];
		switch ((enum fn_op)in->op) {
		case FN_CONST: st[sp++] = in->k; break;
		case FN_ARG: st[sp++] = args[in->i]; break;
		case FN_ADD: sp--; st[sp - 1] += st[sp]; break;
		case FN_SUB: sp--; st[sp - 1] -= st[sp]; break;
		case FN_MUL: sp--; st[sp - 1] *= st[sp]; break;
		case FN_DIV: sp--; st[sp - 1] /= st[sp]; break;
		case FN_NEG: st[sp - 1] = -st[sp - 1]; break;
		case FN_NOT: st[sp - 1] = st[sp - 1] == 0; break;
		case FN_LT: sp--; st[sp - 1] = st[sp - 1] < st[sp]; break;
		case FN_LE: sp--; st[sp - 1] = st[sp - 1] <= st[sp]; break;
		case FN_EQ: sp--; st[sp - 1] = st[sp - 1] == st[sp]; break;
		case FN_GE: sp--; st[sp - 1] = st[sp - 1] >= st[sp]; break;
		case FN_GT: sp--; st[sp - 1] = st[sp - 1] > st[sp]; break;
		case FN_NE: sp--; st[sp - 1] = st[sp - 1] != st[sp]; break;
		case FN_AND: sp--; st[sp - 1] = st[sp - 1] != 0 && st[sp] != 0; break;
		case FN_OR: sp--; st[sp - 1] = st[sp - 1] != 0 || st[sp] != 0; break;
		case FN_CALL1: st[sp - 1] = in->f1(st[sp - 1]); break;
		case FN_CALL2: sp--; st[sp - 1] = in->f2(st[sp - 1], st[sp]); break;
		case FN_MIN:
		case FN_MAX: {
			int n = in->i;
			double r = st[sp - n];
			for (int i = sp - n + 1; i < sp; i++)
				r = in->op == FN_MIN ? fmin(r, st[i]) : fmax(r, st[i]);
			sp -= n;
			st[sp++] = r;
			break;
		}
		case FN_SELECT: {
			int n = in->i;
			double *a = &st[sp - n];
			double r = a[0] < 0 ? a[1] : (n == 3 || a[0] == 0) ? a[2] : a[3];
			sp -= n;
			st[sp++] = r;
			break;
		}
		case FN_USER: {
			int n = in->i;
			sp -= n;
			st[sp] = fn_eval(in->fn, &st[sp]);
			sp++;
			break;
		}
		case FN_INTERNAL: {
			int n = in->i;
			sp -= n;
			st[sp] = fn_internal((int)in->k, &st[sp], n);
			sp++;
			break;
		}
		case FN_SUM:
		case FN_PROD: {
			/* The body is a function of this one's arguments and the loop
			 * variable, which comes last. */
			double lo = st[sp - 2], hi = st[sp - 1];
			sp -= 2;
			double a[FN_MAX_PARAMS];
			int n = f->nparams;
			for (int i = 0; i < n; i++)
				a[i] = args[i];
			double acc = in->op == FN_SUM ? 0 : 1;
			double terms = 0;
			for (double v = lo; v <= hi; v += 1) {
				if ((fn_stop && *fn_stop) || ++terms > fn_max_terms)
					break;
				a[n] = v;
				double x = fn_eval(in->fn, a);
				acc = in->op == FN_SUM ? acc + x : acc * x;
			}
			st[sp++] = acc;
			break;
		}
		case FN_JZ:
			if (st[--sp] == 0)
				pc = in->i - 1;
			break;
		case FN_JMP: pc = in->i - 1; break;
		case FN_PATTERN: {
			/* Parse-time and isosurface calls have no surface: no normal,
			 * no ray; the global noise generator's default. */
			struct pattern_ctx ctx = {.p = {st[sp - 3], st[sp - 2], st[sp - 1]}, .noise_generator = 2};
			sp -= 3;
			st[sp++] = pattern_value(in->pat, &ctx);
			break;
		}
		case FN_PIGMENT: {
			struct pattern_ctx ctx = {.p = {st[sp - 3], st[sp - 2], st[sp - 1]}, .noise_generator = 2};
			sp -= 3;
			struct rgbft c = pigment_eval(in->pig, &ctx);
			double comp[6] = {c.r, c.g, c.b, c.f, c.t, 0.297 * c.r + 0.589 * c.g + 0.114 * c.b};
			st[sp++] = comp[in->i];
			break;
		}
		case FN_VECTOR: {
			int n = in->fn->nparams;
			sp -= n;
			double c[5];
			fn_eval_vector(in->fn, &st[sp], c);
			st[sp++] = in->i == 5 ? 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2] : c[in->i];
			break;
		}
		}
	}
	return sp > 0 ? st[sp - 1] : 0;
}

void fn_eval_color(const struct fn *f, const double *args, double out[5])
{
	struct pattern_ctx ctx = {.p = {args[0], args[1], args[2]}, .noise_generator = 2};
	struct rgbft c = pigment_eval(f->pig, &ctx);
	out[0] = c.r;
	out[1] = c.g;
	out[2] = c.b;
	out[3] = c.f;
	out[4] = c.t;
}

void fn_eval_vector(const struct fn *f, const double *args, double out[5])
{
	if (f->pig) {
		fn_eval_color(f, args, out);
		return;
	}
	if (f->vdim > 0) {
		f->veval(f->vdata, args, out);
		for (int i = f->vdim; i < 5; i++)
			out[i] = 0;
		return;
	}
	out[0] = fn_eval(f, args);
	for (int i = 1; i < 5; i++)
		out[i] = 0;
}
