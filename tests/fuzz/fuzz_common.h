/* Shared pieces of the fuzz harnesses (tests/fuzz/fuzz_*.h): a byte reader
   that turns raw input into values (mostly ordinary ones, sometimes the
   extremes: 0, subnormals, 1e30, the largest finite number, NaN, the
   infinities, raw bit patterns), a failure hook, and an allocator that
   checks sizes and leaks and can fail on request.

   Each harness's per-input function lives in its own header so that the
   libFuzzer driver (tests/fuzz/fuzz_*.c) and the regression suite
   (tests/test_fuzz_regress.c) run the same code.  Everything here compiles
   as C99 and as C++11 under the test suite's warnings. */
#ifndef GA2D_FUZZ_COMMON_H
#define GA2D_FUZZ_COMMON_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ga2d_physics.h"

/* What a violated invariant does.  The libFuzzer drivers keep the default
   (print and abort, so the fuzzer saves the input); the regression suite
   defines it to record a test failure and go on. */
#ifndef FUZZ_FAIL
#define FUZZ_FAIL(file, line, what) \
    (fprintf(stderr, "fuzz invariant violated at %s:%d: %s\n", (file), (line), (what)), abort())
#endif
#define FUZZ_CHECK(cond)                                       \
    do {                                                       \
        if (!(cond)) FUZZ_FAIL(__FILE__, __LINE__, #cond);     \
    } while (0)

#ifdef GA2D_DOUBLE
#define FZ_EPS ((double)DBL_EPSILON)
#define FZ_REAL_MAX ((double)DBL_MAX)
#define FZ_REAL_MIN ((double)DBL_MIN)
#else
#define FZ_EPS ((double)FLT_EPSILON)
#define FZ_REAL_MAX ((double)FLT_MAX)
#define FZ_REAL_MIN ((double)FLT_MIN)
#endif
/* the smallest subnormal (2^-149 in float, 2^-1074 in double): the most a
   result that underflows can be off by */
#define FZ_TINY (FZ_REAL_MIN * FZ_EPS)

/* ------------------------------------------------------------- reader */
typedef struct fz_reader { const uint8_t *p; size_t n, i; } fz_reader;

static inline void fz_init(fz_reader *r, const uint8_t *p, size_t n)
{
    r->p = p;
    r->n = n;
    r->i = 0;
}
static inline int fz_more(const fz_reader *r) { return r->i < r->n; }
/* Past the end every read gives 0, so a short input is still a scene. */
static inline unsigned fz_u8(fz_reader *r) { return r->i < r->n ? r->p[r->i++] : 0u; }
static inline unsigned fz_u16(fz_reader *r)
{
    unsigned lo = fz_u8(r);
    return lo | (fz_u8(r) << 8);
}
static inline uint32_t fz_u32(fz_reader *r)
{
    uint32_t lo = (uint32_t)fz_u16(r);
    return lo | ((uint32_t)fz_u16(r) << 16);
}
static inline uint64_t fz_u64(fz_reader *r)
{
    uint64_t lo = (uint64_t)fz_u32(r);
    return lo | ((uint64_t)fz_u32(r) << 32);
}
/* 0..n-1 */
static inline int fz_pick(fz_reader *r, int n) { return (int)(fz_u8(r) % (unsigned)n); }

/* A double narrowed to ga2d_real without relying on out-of-range
   conversion: beyond the largest finite value it becomes an infinity. */
static inline ga2d_real fz_narrow(double d)
{
    if (d > FZ_REAL_MAX) return (ga2d_real)INFINITY;
    if (d < -FZ_REAL_MAX) return (ga2d_real)-INFINITY;
    return (ga2d_real)d;
}

/* The values fuzzing should try on purpose. */
static inline ga2d_real fz_special(int k)
{
    switch (k & 31) {
    case 0: return 0;
    case 1: return fz_narrow(-0.0);
    case 2: return 1;
    case 3: return -1;
    case 4: return fz_narrow(1e-30);
    case 5: return fz_narrow(-1e-30);
    case 6: return fz_narrow(1e30);
    case 7: return fz_narrow(-1e30);
    case 8: return fz_narrow(1e8);
    case 9: return fz_narrow(-1e8);
    case 10: return fz_narrow(1.0000001e8);
    case 11: return fz_narrow(1e6);
    case 12: return fz_narrow(1e-6);
    case 13: return fz_narrow((double)FLT_MIN);
    case 14: return fz_narrow((double)FLT_MIN / 8); /* subnormal in float */
    case 15: return fz_narrow((double)FLT_MAX);
    case 16: return fz_narrow(-(double)FLT_MAX);
    case 17: return (ga2d_real)NAN;
    case 18: return (ga2d_real)INFINITY;
    case 19: return (ga2d_real)-INFINITY;
    case 20: return fz_narrow(1e15);
    case 21: return fz_narrow(1e4);
    case 22: return fz_narrow(1e-3);
    case 23: return fz_narrow(1e75);
    case 24: return fz_narrow(1.0000001e75);
    case 25: return fz_narrow(FZ_REAL_MAX);
    case 26: return fz_narrow(1e-300); /* 0 in float */
    case 27: return fz_narrow(1e300);  /* inf in float */
    case 28: return fz_narrow(0.5);
    case 29: return fz_narrow(1.0 / 60);
    case 30: return fz_narrow(1e-12);
    default: return fz_narrow(3.0e38);
    }
}

/* A real: mostly k/16 * scale for a small integer k (so that scenes are
   ordinary and bodies touch), sometimes finer, sometimes a special value,
   sometimes raw float or double bits. */
static inline ga2d_real fz_real(fz_reader *r, double scale)
{
    unsigned sel = fz_u8(r);
    if (sel < 150) return fz_narrow((double)(int8_t)fz_u8(r) * scale / 16);
    if (sel < 200) return fz_narrow((double)(int16_t)fz_u16(r) * scale / 4096);
    if (sel < 232) return fz_special((int)(sel - 200));
    if (sel < 248) {
        uint32_t u = fz_u32(r);
        float f;
        memcpy(&f, &u, sizeof f);
        return (ga2d_real)f;
    }
    {
        uint64_t u = fz_u64(r);
        double d;
        memcpy(&d, &u, sizeof d);
        return fz_narrow(d);
    }
}

/* Non-negative version (friction, density, ...): the sign is kept only
   when the special path picked it, so negative values still occur. */
static inline ga2d_real fz_real_pos(fz_reader *r, double scale)
{
    ga2d_real x = fz_real(r, scale);
    return x < 0 && fz_u8(r) < 224 ? -x : x;
}

static inline int fz_finite(double x) { return x - x == 0; }
static inline int fz_finite_vec(ga2d_vec v) { return fz_finite((double)v.x) && fz_finite((double)v.y); }

/* ---------------------------------------------------------- allocator */
/* Every block carries a header with its size, so a free with the wrong
   size is caught; live bytes and blocks are counted; attempt number
   fail_at (1-based, 0 = never) and, after it, every attempt whose number
   is a multiple of fail_every (0 = never) fail. */
typedef struct fz_alloc {
    long attempts, failures, fail_at, fail_every;
    long live_blocks;
    size_t live_bytes;
} fz_alloc;

#define FZ_ALLOC_HEADER 16

static inline void *fz_alloc_fn(size_t size, void *ctx)
{
    fz_alloc *a = (fz_alloc *)ctx;
    unsigned char *p;
    ++a->attempts;
    if (a->attempts == a->fail_at || (a->fail_every > 0 && a->attempts > a->fail_at && a->attempts % a->fail_every == 0)) {
        ++a->failures;
        return NULL;
    }
    p = (unsigned char *)malloc(size + FZ_ALLOC_HEADER);
    if (!p) return NULL;
    memcpy(p, &size, sizeof size);
    ++a->live_blocks;
    a->live_bytes += size;
    return p + FZ_ALLOC_HEADER;
}

static inline void fz_free_fn(void *ptr, size_t size, void *ctx)
{
    fz_alloc *a = (fz_alloc *)ctx;
    unsigned char *p = (unsigned char *)ptr - FZ_ALLOC_HEADER;
    size_t was;
    memcpy(&was, p, sizeof was);
    FUZZ_CHECK(was == size); /* free must get the size that was allocated */
    FUZZ_CHECK(a->live_blocks > 0 && a->live_bytes >= size);
    --a->live_blocks;
    a->live_bytes -= size;
    free(p);
}

static inline void fz_alloc_attach(fz_alloc *a, ga2d_world_def *d)
{
    d->allocator.alloc = fz_alloc_fn;
    d->allocator.free = fz_free_fn;
    d->allocator.ctx = a;
}

#endif
