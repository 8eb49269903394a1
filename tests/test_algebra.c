/* The algebra of G(2,0): the paper's identities (eqs. 3-18), the product
   laws on random multivectors, and the rotor conventions of DESIGN §4.
   Tolerances: each coefficient of a product of multivectors is a sum of at
   most 4 products, so its rounding error is at most 4 eps times the sum of
   the magnitudes of the products, which is <= ||a||_1 ||b||_1 (the 1-norms
   of the coefficients). */
#include "test.h"

static ga2d_mv random_mv(test_rng *r)
{
    return ga2d_mv_make((ga2d_real)rng_uniform(r, -2, 2), (ga2d_real)rng_uniform(r, -2, 2),
                        (ga2d_real)rng_uniform(r, -2, 2), (ga2d_real)rng_uniform(r, -2, 2));
}

static ga2d_vec random_vec(test_rng *r)
{
    return ga2d_vec_make((ga2d_real)rng_uniform(r, -3, 3), (ga2d_real)rng_uniform(r, -3, 3));
}

static double norm1(ga2d_mv m) { return fabs((double)m.s) + fabs((double)m.e1) + fabs((double)m.e2) + fabs((double)m.e12); }

/* largest coefficient difference */
static double mv_diff(ga2d_mv a, ga2d_mv b)
{
    double d = fabs((double)a.s - (double)b.s), t;
    t = fabs((double)a.e1 - (double)b.e1); d = t > d ? t : d;
    t = fabs((double)a.e2 - (double)b.e2); d = t > d ? t : d;
    t = fabs((double)a.e12 - (double)b.e12); d = t > d ? t : d;
    return d;
}

#define CHECK_MV_NEAR(a, b, tol) CHECK_NEAR(mv_diff((a), (b)), 0, (tol))

#define PI_D 3.14159265358979323846

static const ga2d_mv E12 = {0, 0, 0, 1};
static const ga2d_mv ONE = {1, 0, 0, 0};

/* The basis table the header's conventions fix: e1e1 = e2e2 = 1,
   e1e2 = e12 = -e2e1, e12e12 = -1.  Products of basis blades are exact. */
static void basis_products(void)
{
    ga2d_mv e1 = ga2d_mv_make(0, 1, 0, 0), e2 = ga2d_mv_make(0, 0, 1, 0);
    CHECK_MV_NEAR(ga2d_mv_mul(e1, e1), ONE, 0);
    CHECK_MV_NEAR(ga2d_mv_mul(e2, e2), ONE, 0);
    CHECK_MV_NEAR(ga2d_mv_mul(e1, e2), E12, 0);
    CHECK_MV_NEAR(ga2d_mv_mul(e2, e1), ga2d_mv_scale(E12, -1), 0);
    CHECK_MV_NEAR(ga2d_mv_mul(E12, E12), ga2d_mv_scale(ONE, -1), 0);
    CHECK_MV_NEAR(ga2d_mv_mul(e1, E12), e2, 0);
    CHECK_MV_NEAR(ga2d_mv_mul(e2, E12), ga2d_mv_scale(e1, -1), 0);
    CHECK_MV_NEAR(ga2d_mv_mul(E12, e1), ga2d_mv_scale(e2, -1), 0);
    CHECK_MV_NEAR(ga2d_mv_mul(E12, e2), e1, 0);
}

/* Eqs. 9-14: a^b = -b^a, a^a = 0, aa = |a|^2.  wedge(b, a) forms the same
   two products as wedge(a, b) and subtracts them the other way round, so
   the negation is exact (IEEE products commute; the build has no FMA
   contraction).  aa's scalar is x*x + y*y, the same expression as
   |a|^2, and its bivector part is x*y - y*x = 0 exactly. */
static void wedge_antisymmetry_and_square(void)
{
    test_rng rng = {1};
    int i;
    for (i = 0; i < 1000; ++i) {
        ga2d_vec a = random_vec(&rng), b = random_vec(&rng);
        ga2d_mv aa = ga2d_vec_mul(a, a), am = ga2d_mv_from_vec(a), bm = ga2d_mv_from_vec(b);
        CHECK(ga2d_wedge(a, b) == -ga2d_wedge(b, a));
        CHECK(ga2d_wedge(a, a) == 0);
        CHECK(ga2d_vec_outer(a, b).e12 == ga2d_wedge(a, b));
        CHECK_MV_NEAR(ga2d_mv_outer(am, bm), ga2d_mv_scale(ga2d_mv_outer(bm, am), -1), 0);
        CHECK_MV_NEAR(ga2d_mv_outer(am, am), ga2d_mv_make(0, 0, 0, 0), 0);
        CHECK(aa.s == ga2d_vec_length_sq(a) && aa.e1 == 0 && aa.e2 == 0 && aa.e12 == 0);
        /* the same through the general product */
        CHECK_MV_NEAR(ga2d_mv_mul(am, am), ga2d_mv_make(ga2d_vec_length_sq(a), 0, 0, 0), 0);
        /* ab = a.b + a^b (eq. 5 for two vectors): mv_mul adds exact zeros
           to the same products, so this is exact too */
        CHECK_MV_NEAR(ga2d_mv_mul(am, bm), ga2d_vec_mul(a, b), 0);
        CHECK_MV_NEAR(ga2d_vec_mul(a, b), ga2d_mv_make(ga2d_dot(a, b), 0, 0, ga2d_wedge(a, b)), 0);
    }
}

/* a^-1 = a / |a|^2, and eq. 18: B^-1 = (-1)^k B / |B|^2 with k = n(n-1)/2
   for an n-blade: k = 0 for a vector, k = 1 for a bivector.  Each side is a
   few roundings of a value of size 1/|B|: 8 eps |B^-1| covers both. */
static void blade_inverses(void)
{
    test_rng rng = {2};
    int i;
    for (i = 0; i < 1000; ++i) {
        ga2d_vec a = random_vec(&rng), b = random_vec(&rng);
        ga2d_mv am = ga2d_mv_from_vec(a), B = ga2d_mv_outer(am, ga2d_mv_from_vec(b)), inv;
        double a2 = (double)ga2d_vec_length_sq(a), B2 = (double)B.e12 * (double)B.e12;
        if (a2 < 1e-3 || B2 < 1e-3) continue; /* keep both well away from 0 */
        CHECK_RESULT(ga2d_mv_inverse(am, &inv), GA2D_OK);
        CHECK_MV_NEAR(inv, ga2d_mv_scale(am, (ga2d_real)(1.0 / a2)), 8 * REAL_EPS / sqrt(a2));
        CHECK_MV_NEAR(ga2d_mv_mul(am, inv), ONE, 16 * REAL_EPS);
        CHECK_RESULT(ga2d_mv_inverse(B, &inv), GA2D_OK);
        CHECK_MV_NEAR(inv, ga2d_mv_scale(B, (ga2d_real)(-1.0 / B2)), 8 * REAL_EPS / sqrt(B2));
        CHECK_MV_NEAR(ga2d_mv_mul(B, inv), ONE, 16 * REAL_EPS);
    }
}

/* Eq. 5: for a vector a and ANY multivector B, aB = a _| B + a ^ B.  Both
   sides sum the same products in different groupings: 8 eps ||a|| ||B||. */
static void product_splits_into_inner_and_outer(void)
{
    test_rng rng = {3};
    int i;
    for (i = 0; i < 1000; ++i) {
        ga2d_mv a = ga2d_mv_from_vec(random_vec(&rng)), B = random_mv(&rng);
        ga2d_mv lhs = ga2d_mv_mul(a, B), rhs = ga2d_mv_add(ga2d_mv_inner(a, B), ga2d_mv_outer(a, B));
        CHECK_MV_NEAR(lhs, rhs, 8 * REAL_EPS * norm1(a) * norm1(B));
    }
    /* eq. 3: e1 _| (e1 ^ e2) = e2 (the collapse of B along e1) */
    CHECK_MV_NEAR(ga2d_mv_inner(ga2d_mv_make(0, 1, 0, 0), E12), ga2d_mv_make(0, 0, 1, 0), 0);
    /* a contraction never raises grade: a bivector into a vector is 0 */
    CHECK_MV_NEAR(ga2d_mv_inner(E12, ga2d_mv_make(0, 1, 1, 0)), ga2d_mv_make(0, 0, 0, 0), 0);
}

/* Eq. 4, the projection of v onto a blade B, written with the left
   contraction: p = (v _| B) B^-1.  Onto a line b it is the familiar
   (v.b) b / |b|^2, with v - p perpendicular to b; onto the plane e12 it
   returns v.  Each is a product of two products and an inverse: with
   |v|, |b| <= 3*sqrt(2), 64 eps |v| covers the roundings. */
static void projection_onto_blades(void)
{
    test_rng rng = {4};
    int i;
    for (i = 0; i < 1000; ++i) {
        ga2d_vec v = random_vec(&rng), b = random_vec(&rng), bhat;
        ga2d_mv vm = ga2d_mv_from_vec(v), bm = ga2d_mv_from_vec(b), binv, Binv, p;
        double lv = (double)ga2d_vec_length(v);
        if ((double)ga2d_vec_normalize(b, &bhat) < 1e-2) continue;
        CHECK_RESULT(ga2d_mv_inverse(bm, &binv), GA2D_OK);
        p = ga2d_mv_mul(ga2d_mv_inner(vm, bm), binv);
        CHECK_NEAR(p.s, 0, 0);
        CHECK_NEAR(p.e12, 0, 0);
        CHECK_NEAR(ga2d_wedge(ga2d_mv_vec_part(p), bhat), 0, 64 * REAL_EPS * lv);
        CHECK_NEAR(ga2d_dot(ga2d_vec_sub(v, ga2d_mv_vec_part(p)), bhat), 0, 64 * REAL_EPS * lv);
        CHECK_NEAR(ga2d_dot(ga2d_mv_vec_part(p), bhat), ga2d_dot(v, bhat), 64 * REAL_EPS * lv);
        /* onto the plane B = 2.5 e12: every vector lies in it */
        CHECK_RESULT(ga2d_mv_inverse(ga2d_mv_scale(E12, 2.5), &Binv), GA2D_OK);
        p = ga2d_mv_mul(ga2d_mv_inner(vm, ga2d_mv_scale(E12, 2.5)), Binv);
        CHECK_MV_NEAR(p, vm, 16 * REAL_EPS * lv);
    }
}

/* Associativity and distributivity on random multivectors.  Each side of
   (ab)c = a(bc) carries <= 4 eps ||a|| ||b|| ||c|| from each of its two
   products (the inner product's error propagates through the outer one
   with the same 1-norm factor): the sides differ by <= 16 eps of that. */
static void product_laws(void)
{
    test_rng rng = {5};
    int i;
    for (i = 0; i < 2000; ++i) {
        ga2d_mv a = random_mv(&rng), b = random_mv(&rng), c = random_mv(&rng);
        double p3 = norm1(a) * norm1(b) * norm1(c);
        double p2 = norm1(a) * (norm1(b) + norm1(c));
        CHECK_MV_NEAR(ga2d_mv_mul(ga2d_mv_mul(a, b), c), ga2d_mv_mul(a, ga2d_mv_mul(b, c)), 16 * REAL_EPS * p3);
        CHECK_MV_NEAR(ga2d_mv_outer(ga2d_mv_outer(a, b), c), ga2d_mv_outer(a, ga2d_mv_outer(b, c)), 16 * REAL_EPS * p3);
        CHECK_MV_NEAR(ga2d_mv_mul(a, ga2d_mv_add(b, c)), ga2d_mv_add(ga2d_mv_mul(a, b), ga2d_mv_mul(a, c)), 16 * REAL_EPS * p2);
        CHECK_MV_NEAR(ga2d_mv_mul(ga2d_mv_add(b, c), a), ga2d_mv_add(ga2d_mv_mul(b, a), ga2d_mv_mul(c, a)), 16 * REAL_EPS * p2);
        /* reversion reverses products: (ab)~ = b~ a~; involution is an
           automorphism: (ab)^ = a^ b^.  Same products, other groupings. */
        CHECK_MV_NEAR(ga2d_mv_reverse(ga2d_mv_mul(a, b)), ga2d_mv_mul(ga2d_mv_reverse(b), ga2d_mv_reverse(a)), 8 * REAL_EPS * norm1(a) * norm1(b));
        CHECK_MV_NEAR(ga2d_mv_involute(ga2d_mv_mul(a, b)), ga2d_mv_mul(ga2d_mv_involute(a), ga2d_mv_involute(b)), 8 * REAL_EPS * norm1(a) * norm1(b));
        /* the Clifford conjugate is both at once */
        CHECK_MV_NEAR(ga2d_mv_conjugate(a), ga2d_mv_reverse(ga2d_mv_involute(a)), 0);
    }
}

/* Grades, dual and norm.  All exact: they only move and negate numbers,
   except the norm, whose square is 4 products summed (4 eps |m|^2). */
static void grades_dual_norm(void)
{
    test_rng rng = {6};
    int i;
    for (i = 0; i < 500; ++i) {
        ga2d_mv m = random_mv(&rng), sum = ga2d_mv_make(0, 0, 0, 0), mr;
        double n2;
        int k;
        for (k = 0; k <= 2; ++k) sum = ga2d_mv_add(sum, ga2d_mv_grade(m, k));
        CHECK_MV_NEAR(sum, m, 0);
        CHECK_MV_NEAR(ga2d_mv_grade(m, 3), ga2d_mv_make(0, 0, 0, 0), 0);
        CHECK_MV_NEAR(ga2d_mv_grade(m, -1), ga2d_mv_make(0, 0, 0, 0), 0);
        /* dual = m I^-1 with I^-1 = -e12; applied twice it is -m */
        CHECK_MV_NEAR(ga2d_mv_dual(m), ga2d_mv_mul(m, ga2d_mv_scale(E12, -1)), 0);
        CHECK_MV_NEAR(ga2d_mv_dual(ga2d_mv_dual(m)), ga2d_mv_scale(m, -1), 0);
        mr = ga2d_mv_mul(m, ga2d_mv_reverse(m));
        n2 = (double)ga2d_mv_norm(m) * (double)ga2d_mv_norm(m);
        CHECK_NEAR(n2, mr.s, 8 * REAL_EPS * n2);
    }
    /* the norm of a huge multivector does not overflow: 2e30 fits a float */
    CHECK_NEAR(ga2d_mv_norm(ga2d_mv_make((ga2d_real)1e30, (ga2d_real)1e30, (ga2d_real)1e30, (ga2d_real)1e30)), 2e30, 8 * REAL_EPS * 2e30);
}

/* m m^-1 = m^-1 m = 1.  m^-1 = conj(m)/det with det = m conj(m); relative
   error of the product <= (4 + 4) eps ||m||^2 / |det| (det's own rounding
   and the product's), so cases are kept to |det| >= ||m||_2^2 / 10. */
static void general_inverse(void)
{
    test_rng rng = {7};
    int i, tested = 0;
    for (i = 0; i < 2000; ++i) {
        ga2d_mv m = random_mv(&rng), inv;
        double n2 = (double)(m.s * m.s + m.e1 * m.e1 + m.e2 * m.e2 + m.e12 * m.e12);
        double det = (double)m.s * (double)m.s - (double)m.e1 * (double)m.e1 - (double)m.e2 * (double)m.e2 + (double)m.e12 * (double)m.e12;
        if (fabs(det) < n2 / 10) continue;
        ++tested;
        CHECK_RESULT(ga2d_mv_inverse(m, &inv), GA2D_OK);
        CHECK_MV_NEAR(ga2d_mv_mul(m, inv), ONE, 16 * REAL_EPS * n2 / fabs(det) * 4);
        CHECK_MV_NEAR(ga2d_mv_mul(inv, m), ONE, 16 * REAL_EPS * n2 / fabs(det) * 4);
    }
    CHECK(tested > 500);
}

/* 1 + e1 squares its own conjugate away: (1 + e1)(1 - e1) = 0, so it is a
   zero divisor with no inverse; likewise e1 + e12, 0, and 1+e1+e2+e12.
   The call must say so and leave *out as it was. */
static void non_invertible_is_reported(void)
{
    const ga2d_mv bad[] = {{1, 1, 0, 0}, {0, 1, 0, 1}, {0, 0, 0, 0}, {1, 1, 1, 1}, {3, 0, -3, 0}, {0, 3, 4, 5}};
    const ga2d_mv sentinel = {7, 7, 7, 7};
    size_t i;
    for (i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        ga2d_mv out = sentinel;
        CHECK_RESULT(ga2d_mv_inverse(bad[i], &out), GA2D_ERR_NOT_INVERTIBLE);
        CHECK(memcmp(&out, &sentinel, sizeof out) == 0);
    }
    /* 1 + u for any unit vector u is a zero divisor too, but rounding in u
       leaves m conj(m) = 1 - |u|^2 a few eps off zero instead of 0: the
       tolerance must still call it non-invertible, not return ~1e7 */
    {
        test_rng rng = {13};
        for (i = 0; i < 1000; ++i) {
            double t = rng_uniform(&rng, -PI_D, PI_D);
            ga2d_mv out = sentinel;
            ga2d_vec u;
            ga2d_vec_normalize(ga2d_vec_make((ga2d_real)cos(t), (ga2d_real)sin(t)), &u);
            CHECK_RESULT(ga2d_mv_inverse(ga2d_mv_make(1, u.x, u.y, 0), &out), GA2D_ERR_NOT_INVERTIBLE);
            /* and e12 + u: (e12 + u) conj = -|u|^2 + 1 as well */
            CHECK_RESULT(ga2d_mv_inverse(ga2d_mv_make(0, u.x, u.y, 1), &out), GA2D_ERR_NOT_INVERTIBLE);
            CHECK(memcmp(&out, &sentinel, sizeof out) == 0);
        }
    }
    {
        ga2d_mv out = sentinel;
        CHECK_RESULT(ga2d_mv_inverse(ga2d_mv_make((ga2d_real)NAN, 0, 0, 0), &out), GA2D_ERR_NOT_FINITE);
        CHECK_RESULT(ga2d_mv_inverse(ga2d_mv_make(0, (ga2d_real)INFINITY, 0, 0), &out), GA2D_ERR_NOT_FINITE);
        CHECK_RESULT(ga2d_mv_inverse(ONE, NULL), GA2D_ERR_INVALID_ARGUMENT);
        CHECK(memcmp(&out, &sentinel, sizeof out) == 0);
    }
}

/* Normalize reports a zero length instead of dividing by it, and neither
   overflows nor underflows where |v| itself is representable. */
static void vector_length_and_normalize(void)
{
    ga2d_vec u;
    ga2d_real big = (ga2d_real)(REAL_MAX / 2); /* big*big overflows */
    CHECK(ga2d_vec_normalize(ga2d_vec_make(0, 0), &u) == 0 && u.x == 0 && u.y == 0);
    /* a subnormal length: 1/len would overflow */
    CHECK(ga2d_vec_normalize(ga2d_vec_make((ga2d_real)(REAL_MIN / 16), 0), &u) == 0 && u.x == 0 && u.y == 0);
    CHECK(ga2d_vec_normalize(ga2d_vec_make((ga2d_real)NAN, 1), &u) == 0 && u.x == 0 && u.y == 0);
    CHECK(ga2d_vec_normalize(ga2d_vec_make((ga2d_real)INFINITY, 1), &u) == 0 && u.x == 0 && u.y == 0);
    CHECK(ga2d_vec_normalize(ga2d_vec_make(3, 4), NULL) == 5);
    /* 3-4-5: sqrt(0.36 + 0.64) = 1 within a rounding, times 5 */
    CHECK_NEAR(ga2d_vec_normalize(ga2d_vec_make(3, 4), &u), 5, 4 * REAL_EPS * 5);
    CHECK_NEAR(u.x, 0.6, 2 * REAL_EPS);
    CHECK_NEAR(u.y, 0.8, 2 * REAL_EPS);
    /* |(big, big)| = big sqrt 2 < FLT_MAX, although big^2 is not finite */
    CHECK_NEAR(ga2d_vec_length(ga2d_vec_make(big, big)), (double)big * sqrt(2.0), 4 * REAL_EPS * (double)big * 1.5);
    CHECK_NEAR(ga2d_vec_normalize(ga2d_vec_make(big, big), &u), (double)big * sqrt(2.0), 4 * REAL_EPS * (double)big * 1.5);
    CHECK_NEAR(u.x, sqrt(0.5), 4 * REAL_EPS);
    /* a tiny vector whose square underflows still has its length */
    {
        double tiny = sqrt(REAL_MIN) / 1024; /* tiny^2 is deep in the subnormals */
        CHECK_NEAR(ga2d_vec_length(ga2d_vec_make((ga2d_real)(3 * tiny), (ga2d_real)(4 * tiny))), 5 * tiny, 4 * REAL_EPS * 5 * tiny);
    }
    CHECK_NEAR(ga2d_vec_length(ga2d_vec_make(-3, -4)), 5, 4 * REAL_EPS * 5);
}

/* v e12 turns v by +90 degrees: perp is exactly the geometric product. */
static void perp_is_right_multiplication_by_e12(void)
{
    test_rng rng = {8};
    int i;
    for (i = 0; i < 200; ++i) {
        ga2d_vec v = random_vec(&rng);
        ga2d_mv p = ga2d_mv_mul(ga2d_mv_from_vec(v), E12);
        CHECK_MV_NEAR(p, ga2d_mv_from_vec(ga2d_vec_perp(v)), 0);
        CHECK(ga2d_dot(v, ga2d_vec_perp(v)) == 0);
        CHECK(ga2d_wedge(v, ga2d_vec_perp(v)) >= 0); /* counter-clockwise */
    }
}

/* DESIGN §4: v q with q = exp(theta e12) equals the sandwich R v R~ with
   R = exp(-theta e12 / 2), computed here through the general product.
   Both sides are products of numbers of size <= |v| with cos/sin values
   that libm gives within an ulp or two: 16 eps |v| covers it. */
static void sandwich_equals_right_multiplication(void)
{
    test_rng rng = {9};
    int i;
    for (i = 0; i < 2000; ++i) {
        double theta = i < 8 ? (i - 4) * 3.14159265358979323846 / 4 : rng_uniform(&rng, -20, 20);
        ga2d_vec v = random_vec(&rng);
        ga2d_rotor q = ga2d_rotor_from_angle((ga2d_real)theta);
        ga2d_mv R = ga2d_mv_from_rotor(ga2d_rotor_from_angle((ga2d_real)(-theta / 2)));
        ga2d_mv sandwich = ga2d_mv_mul(ga2d_mv_mul(R, ga2d_mv_from_vec(v)), ga2d_mv_reverse(R));
        ga2d_vec vq = ga2d_rotate(q, v);
        double lv = (double)ga2d_vec_length(v);
        CHECK_NEAR(sandwich.s, 0, 16 * REAL_EPS * lv);
        CHECK_NEAR(sandwich.e12, 0, 16 * REAL_EPS * lv);
        CHECK_NEAR(sandwich.e1, vq.x, 16 * REAL_EPS * lv);
        CHECK_NEAR(sandwich.e2, vq.y, 16 * REAL_EPS * lv);
        /* and v q is the geometric product of v with q, to the bit */
        CHECK_MV_NEAR(ga2d_mv_mul(ga2d_mv_from_vec(v), ga2d_mv_from_rotor(q)), ga2d_mv_from_vec(vq), 0);
        /* counter-clockwise by theta: the angle of v q minus that of v */
        CHECK_NEAR(ga2d_wedge(v, vq), lv * lv * sin(theta), 16 * REAL_EPS * lv * lv);
        CHECK_NEAR(ga2d_dot(v, vq), lv * lv * cos(theta), 16 * REAL_EPS * lv * lv);
        /* rotate_inv undoes rotate: two rotations of size-|v| values */
        CHECK_NEAR(ga2d_rotate_inv(q, vq).x, v.x, 8 * REAL_EPS * lv);
        CHECK_NEAR(ga2d_rotate_inv(q, vq).y, v.y, 8 * REAL_EPS * lv);
    }
    /* e1 turned a quarter turn is e2 */
    CHECK_NEAR(ga2d_rotate(ga2d_rotor_from_angle((ga2d_real)(3.14159265358979323846 / 2)), ga2d_vec_make(1, 0)).y, 1, 2 * REAL_EPS);
}

/* log(exp(b)) = b for b in (-pi, pi]; exp(log q) = q; q q~ = 1.  atan2,
   sin and cos are within 1-2 ulp; near +-pi the angle's ulp is pi eps, so
   8 pi eps bounds the round trip. */
static void rotor_exp_log_inverse(void)
{
    test_rng rng = {10};
    int i;
    for (i = 0; i < 2000; ++i) {
        ga2d_bivec b;
        ga2d_rotor q, qq;
        b.e12 = (ga2d_real)rng_uniform(&rng, -3.14159, 3.14159);
        q = ga2d_rotor_exp(b);
        CHECK_NEAR(ga2d_rotor_log(q).e12, b.e12, 8 * 3.1416 * REAL_EPS);
        CHECK_NEAR(ga2d_rotor_angle(q), b.e12, 8 * 3.1416 * REAL_EPS);
        qq = ga2d_rotor_exp(ga2d_rotor_log(q));
        CHECK_NEAR(qq.c, q.c, 8 * 3.1416 * REAL_EPS);
        CHECK_NEAR(qq.s, q.s, 8 * 3.1416 * REAL_EPS);
        qq = ga2d_rotor_mul(q, ga2d_rotor_inverse(q)); /* c^2 + s^2 and c s - s c */
        CHECK_NEAR(qq.c, 1, 4 * REAL_EPS);
        CHECK(qq.s == 0);
        /* exp(b e12) is cos b + sin b e12: the even part of a rotor is a
           complex number and the conversions keep it */
        CHECK_NEAR(ga2d_rotor_from_mv(ga2d_mv_from_rotor(q)).c, q.c, 2 * REAL_EPS);
        CHECK_NEAR(ga2d_rotor_from_mv(ga2d_mv_from_rotor(q)).s, q.s, 2 * REAL_EPS);
    }
}

/* q1 q2 adds angles; the sum is taken modulo 2 pi by comparing rotors. */
static void rotor_composition(void)
{
    test_rng rng = {11};
    int i;
    for (i = 0; i < 2000; ++i) {
        double a = rng_uniform(&rng, -10, 10), b = rng_uniform(&rng, -10, 10);
        ga2d_rotor q = ga2d_rotor_mul(ga2d_rotor_from_angle((ga2d_real)a), ga2d_rotor_from_angle((ga2d_real)b));
        ga2d_rotor p = ga2d_rotor_mul(ga2d_rotor_from_angle((ga2d_real)b), ga2d_rotor_from_angle((ga2d_real)a));
        /* float inputs a, b carry up to 10 eps/2 of rounding each, which the
           angle keeps: 16 (|a|+|b|) eps bounds it */
        double tol = 16 * REAL_EPS * (fabs(a) + fabs(b) + 1);
        CHECK_NEAR(q.c, cos((double)(ga2d_real)a + (double)(ga2d_real)b), tol);
        CHECK_NEAR(q.s, sin((double)(ga2d_real)a + (double)(ga2d_real)b), tol);
        CHECK(q.c == p.c && q.s == p.s); /* commutative in the plane, exactly */
    }
}

static void rotor_normalize_nlerp_between(void)
{
    test_rng rng = {12};
    ga2d_rotor q = ga2d_rotor_normalize(ga2d_rotor_identity());
    ga2d_rotor zero, half;
    int i;
    CHECK(q.c == 1 && q.s == 0);
    q.c = 3; q.s = 4;
    q = ga2d_rotor_normalize(q);
    CHECK_NEAR(q.c, 0.6, 2 * REAL_EPS);
    CHECK_NEAR(q.s, 0.8, 2 * REAL_EPS);
    zero.c = 0; zero.s = 0;
    q = ga2d_rotor_normalize(zero);
    CHECK(q.c == 1 && q.s == 0); /* documented: identity, never NaN */
    zero.c = (ga2d_real)NAN;
    q = ga2d_rotor_normalize(zero);
    CHECK(q.c == 1 && q.s == 0);
    /* a first-order update drifts off the unit circle; normalize brings it
       back to |q| = 1 within a rounding or two */
    q = ga2d_rotor_from_angle((ga2d_real)0.375);
    q.c *= (ga2d_real)1.01; q.s *= (ga2d_real)1.01;
    q = ga2d_rotor_normalize(q);
    CHECK_NEAR(q.c * q.c + q.s * q.s, 1, 4 * REAL_EPS);
    CHECK_NEAR(ga2d_rotor_angle(q), 0.375, 8 * REAL_EPS);

    for (i = 0; i < 500; ++i) {
        double a = rng_uniform(&rng, -3, 3), d = rng_uniform(&rng, -2.5, 2.5), t = rng_uniform(&rng, 0, 1);
        ga2d_rotor qa = ga2d_rotor_from_angle((ga2d_real)a), qb = ga2d_rotor_from_angle((ga2d_real)(a + d));
        ga2d_rotor m = ga2d_rotor_nlerp(qa, qb, (ga2d_real)t);
        double ang = (double)ga2d_rotor_angle(ga2d_rotor_mul(m, ga2d_rotor_inverse(qa)));
        CHECK_NEAR(m.c * m.c + m.s * m.s, 1, 4 * REAL_EPS);
        /* nlerp follows the shorter arc: the angle from a lies between 0
           and d, and at t = 1/2 the chord's midpoint is exactly half way */
        CHECK(ang * d >= -8 * REAL_EPS && fabs(ang) <= fabs(d) + 8 * REAL_EPS);
        if (i == 0) {
            m = ga2d_rotor_nlerp(qa, qb, 0.5);
            CHECK_NEAR(ga2d_rotor_angle(ga2d_rotor_mul(m, ga2d_rotor_inverse(qa))), d / 2, 32 * REAL_EPS);
        }
    }
    /* endpoints */
    half = ga2d_rotor_nlerp(ga2d_rotor_from_angle((ga2d_real)0.25), ga2d_rotor_from_angle((ga2d_real)1.125), 0);
    CHECK_NEAR(ga2d_rotor_angle(half), 0.25, 8 * REAL_EPS);
    half = ga2d_rotor_nlerp(ga2d_rotor_from_angle((ga2d_real)0.25), ga2d_rotor_from_angle((ga2d_real)1.125), 1);
    CHECK_NEAR(ga2d_rotor_angle(half), 1.125, 8 * REAL_EPS);
    /* exactly opposite rotors: no shorter arc, documented to turn CCW */
    half = ga2d_rotor_nlerp(ga2d_rotor_identity(), ga2d_rotor_from_angle((ga2d_real)3.14159265358979323846), 0.5);
    CHECK_NEAR(ga2d_rotor_angle(half), 3.14159265358979323846 / 2, 8 * REAL_EPS);
    /* b = -a exactly (negation is exact), so the chord's midpoint is 0 */
    {
        ga2d_rotor a = ga2d_rotor_from_angle((ga2d_real)0.5), b;
        b.c = -a.c;
        b.s = -a.s;
        half = ga2d_rotor_nlerp(a, b, 0.5);
        CHECK_NEAR(half.c * half.c + half.s * half.s, 1, 4 * REAL_EPS);
        CHECK_NEAR(ga2d_rotor_angle(half), 0.5 + 3.14159265358979323846 / 2, 16 * REAL_EPS);
    }

    /* rotor_between: the rotor turning a's direction onto b's */
    for (i = 0; i < 500; ++i) {
        ga2d_vec a = random_vec(&rng), b = random_vec(&rng), ahat, bhat, turned;
        if ((double)ga2d_vec_normalize(a, &ahat) < 1e-2 || (double)ga2d_vec_normalize(b, &bhat) < 1e-2) continue;
        turned = ga2d_rotate(ga2d_rotor_between(a, b), ahat);
        CHECK_NEAR(turned.x, bhat.x, 16 * REAL_EPS);
        CHECK_NEAR(turned.y, bhat.y, 16 * REAL_EPS);
    }
    q = ga2d_rotor_between(ga2d_vec_make(0, 0), ga2d_vec_make(1, 0));
    CHECK(q.c == 1 && q.s == 0);
}

void suite_algebra(void)
{
    test_run("algebra: basis product table", basis_products);
    test_run("algebra: a^b = -b^a, a^a = 0, aa = |a|^2 (eqs. 9-14)", wedge_antisymmetry_and_square);
    test_run("algebra: a^-1 = a/|a|^2, B^-1 = (-1)^k B/|B|^2 (eq. 18)", blade_inverses);
    test_run("algebra: aB = a.B + a^B (eq. 5)", product_splits_into_inner_and_outer);
    test_run("algebra: projection p = (v.B) B^-1 (eq. 4)", projection_onto_blades);
    test_run("algebra: associativity, distributivity, reverse, involution", product_laws);
    test_run("algebra: grade projection, dual, norm", grades_dual_norm);
    test_run("algebra: general inverse m m^-1 = 1", general_inverse);
    test_run("algebra: non-invertible input is reported (1 + e1)", non_invertible_is_reported);
    test_run("algebra: length without overflow, normalize reports zero", vector_length_and_normalize);
    test_run("algebra: perp is v e12", perp_is_right_multiplication_by_e12);
    test_run("algebra: sandwich R v R~ equals v q", sandwich_equals_right_multiplication);
    test_run("algebra: rotor exp/log round trip, q q~ = 1", rotor_exp_log_inverse);
    test_run("algebra: rotor composition adds angles", rotor_composition);
    test_run("algebra: rotor normalize, nlerp, between", rotor_normalize_nlerp_between);
}
