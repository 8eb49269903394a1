/* A minimal test framework for ga2d_physics: each test is a function, each
   suite a function that runs its tests through test_run().  The runner's
   last line is "N passed, N failed" (tests, not checks). */
#ifndef GA2D_TEST_H
#define GA2D_TEST_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ga2d_physics.h"

#ifdef GA2D_DOUBLE
#define REAL_EPS ((double)DBL_EPSILON)
#define REAL_NAME "double"
#define REAL_MIN ((double)DBL_MIN)
#define REAL_MAX ((double)DBL_MAX)
#else
#define REAL_EPS ((double)FLT_EPSILON)
#define REAL_NAME "float"
#define REAL_MIN ((double)FLT_MIN)
#define REAL_MAX ((double)FLT_MAX)
#endif

#ifdef __cplusplus
extern "C" {
#endif

void test_run(const char *name, void (*fn)(void));
void test_fail(const char *file, int line, const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* splitmix64: a deterministic generator, so every run tests the same cases */
typedef struct test_rng { uint64_t state; } test_rng;
uint64_t rng_next(test_rng *r);
double rng_uniform(test_rng *r, double lo, double hi);
int rng_int(test_rng *r, int lo, int hi); /* lo..hi inclusive */

/* suites */
void suite_algebra(void);
void suite_polygon(void);
void suite_mass(void);
void suite_config(void);
void suite_world(void);
void suite_motion(void);
void suite_collide(void);
void suite_contacts(void);
void suite_solver(void);
void suite_determinism(void);
void suite_snapshot(void);
void suite_containment(void);
void suite_fuzz_regress(void);
void suite_failinject(void);
void suite_extremes(void);
void suite_hostile(void);
void suite_shape_mass(void);
void suite_shape_collide(void);
void suite_shape_world(void);
void suite_shape_terrain(void);
void suite_shape_dynamics(void);
void suite_features(void);
void suite_settle(void);
void suite_accepted(void);
void suite_joints(void);
void suite_joints_kinds(void);
void suite_joints_scenes(void);
void suite_joints_extremes(void);
void suite_queries(void);
void suite_continuous(void);
void suite_mover(void);
void suite_restitution_fast(void);
void suite_threads(void);

#ifdef __cplusplus
}
#endif

#define CHECK(cond)                                                       \
    do {                                                                  \
        if (!(cond)) test_fail(__FILE__, __LINE__, "CHECK(%s)", #cond);    \
    } while (0)

/* |a - b| <= tol, everything compared in double */
#define CHECK_NEAR(a, b, tol)                                                          \
    do {                                                                               \
        double a_ = (double)(a), b_ = (double)(b), t_ = (double)(tol);                 \
        if (!(fabs(a_ - b_) <= t_))                                                    \
            test_fail(__FILE__, __LINE__, "%s = %.17g vs %s = %.17g: |diff| %.3g > %.3g", \
                      #a, a_, #b, b_, fabs(a_ - b_), t_);                              \
    } while (0)

#define CHECK_RESULT(expr, expected)                                                    \
    do {                                                                                \
        ga2d_result r_ = (expr), e_ = (expected);                                       \
        if (r_ != e_)                                                                   \
            test_fail(__FILE__, __LINE__, "%s returned \"%s\", expected \"%s\"", #expr, \
                      ga2d_result_string(r_), ga2d_result_string(e_));                  \
    } while (0)

#endif
