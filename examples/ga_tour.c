/* ga_tour.c - a guided tour of ga2d_physics.h, following the seed paper
   "Planar Physics for Computer Simulation with Geometric Algebra".
   Read it top to bottom: each step prints what the library computes next
   to what the algebra predicts, using only the public API.  The exit
   status is 0 when every value agrees with its closed form. */
#define GA2D_IMPLEMENTATION
#include "ga2d_physics.h"
#include <math.h>
#include <stdio.h>

static int mismatches = 0;

/* float builds keep ~7 digits, so agree to 1e-4 (relative above 1) */
static int close_to(double got, double want)
{
    return fabs(got - want) <= 1e-4 * (fabs(want) > 1 ? fabs(want) : 1);
}
static void verdict(int ok)
{
    if (!ok) ++mismatches;
    printf("%s\n", ok ? "" : "   <-- MISMATCH");
}
/* rounding residue such as 3e-8 prints as 0, and -0 as 0 */
static double z(ga2d_real x) { return fabs((double)x) < 5e-7 ? 0.0 : (double)x; }

static void row(const char *what, ga2d_real got, double want)
{
    printf("  %-36s %9.5f    expected %9.5f", what, z(got), want);
    verdict(close_to((double)got, want));
}
static void vrow(const char *what, ga2d_vec v, double x, double y)
{
    printf("  %-36s (%.5f, %.5f)    expected (%.5f, %.5f)", what, z(v.x), z(v.y), x, y);
    verdict(close_to((double)v.x, x) && close_to((double)v.y, y));
}
/* a multivector as [scalar, e1, e2, e12] */
static void mrow(const char *what, ga2d_mv m, double s, double e1, double e2, double e12)
{
    printf("  %-36s [%g, %g, %g, %g]    expected [%g, %g, %g, %g]", what,
           z(m.s), z(m.e1), z(m.e2), z(m.e12), s, e1, e2, e12);
    verdict(close_to((double)m.s, s) && close_to((double)m.e1, e1) &&
            close_to((double)m.e2, e2) && close_to((double)m.e12, e12));
}
static void rrow(const char *what, ga2d_result got, ga2d_result want)
{
    printf("  %-36s \"%s\"    expected \"%s\"", what, ga2d_result_string(got), ga2d_result_string(want));
    verdict(got == want);
}

int main(void)
{
    const double PI = 3.14159265358979323846;
    ga2d_vec a = ga2d_vec_make(3, 1), b = ga2d_vec_make(1, 3), v = ga2d_vec_make(1, 2);
    ga2d_mv A = ga2d_mv_from_vec(a), V = ga2d_mv_from_vec(v);
    ga2d_mv B = ga2d_mv_from_bivec(ga2d_vec_outer(a, b)); /* the 2-blade a^b = 8 e12 */
    ga2d_mv a_inv = ga2d_mv_make(0, 0, 0, 0), B_inv = a_inv, scratch = a_inv;

    printf("ga2d_physics tour (ga2d_real is %s)\n", sizeof(ga2d_real) == sizeof(double) ? "double" : "float");

    /* 1. The geometric product of two vectors splits into a symmetric
       scalar part and an antisymmetric bivector part (eq. 5). */
    printf("\n1. Vectors a = 3e1 + e2, b = e1 + 3e2  (eqs. 5, 9-14)\n");
    row("a.b", ga2d_dot(a, b), 6);
    row("a^b  (e12 coefficient)", ga2d_wedge(a, b), 8);
    mrow("ab = a.b + a^b  (eq. 5)", ga2d_vec_mul(a, b), 6, 0, 0, 8);
    row("b^a = -(a^b)  (anticommutes)", ga2d_wedge(b, a), -8);
    mrow("aa = a.a + a^a = |a|^2  (eq. 9)", ga2d_vec_mul(a, a), 10, 0, 0, 0);
    /* eqs. 10-14: collapsing and extruding B by a gives back |a|^2 B */
    mrow("a(aB) = |a|^2 B  (eq. 14)", ga2d_mv_mul(A, ga2d_mv_mul(A, B)), 0, 0, 0, 80);

    /* 2. Since aa = |a|^2 is a scalar, a^-1 = a/|a|^2; a 2-blade squares
       to -|B|^2 (k = 1 in eq. 18), hence the minus sign in B^-1. */
    printf("\n2. Inverses  (eq. 18)\n");
    rrow("ga2d_mv_inverse(a)", ga2d_mv_inverse(A, &a_inv), GA2D_OK);
    mrow("a^-1 = a/|a|^2", a_inv, 0, 0.3, 0.1, 0);
    mrow("a a^-1", ga2d_mv_mul(A, a_inv), 1, 0, 0, 0);
    rrow("ga2d_mv_inverse(B = a^b)", ga2d_mv_inverse(B, &B_inv), GA2D_OK);
    mrow("B^-1 = -B/|B|^2", B_inv, 0, 0, 0, -0.125);
    mrow("B B^-1", ga2d_mv_mul(B, B_inv), 1, 0, 0, 0);
    /* (1 + e1)(1 - e1) = 1 - e1 e1 = 0: a zero divisor has no inverse */
    rrow("ga2d_mv_inverse(1 + e1)", ga2d_mv_inverse(ga2d_mv_make(1, 1, 0, 0), &scratch), GA2D_ERR_NOT_INVERTIBLE);

    /* 3. Eq. 4 with left contraction: v _| X keeps the part of v inside
       the blade X, and X^-1 undoes the collapse (eq. 3). */
    printf("\n3. Projection p = (v _| X) X^-1, v = e1 + 2e2  (eq. 4)\n");
    {
        ga2d_mv p = ga2d_mv_mul(ga2d_mv_inner(V, A), a_inv);
        mrow("onto the line of a: (v.a) a^-1", p, 0, 1.5, 0.5, 0);
        row("(v - p).a  (the rest is normal to a)", ga2d_dot(ga2d_vec_sub(v, ga2d_mv_vec_part(p)), a), 0);
        /* every vector of the plane lies in B, so it projects to itself */
        mrow("onto the plane B: (v _| B) B^-1", ga2d_mv_mul(ga2d_mv_inner(V, B), B_inv), 0, 1, 2, 0);
    }

    /* 4. e12 e12 = -1, so exp(theta e12) = cos + sin e12 (Euler) and
       v q turns v counter-clockwise by theta. */
    printf("\n4. Rotors q = exp(theta e12), theta = pi/6\n");
    {
        double th = PI / 6, c = cos(th), s = sin(th);
        ga2d_rotor q = ga2d_rotor_from_angle((ga2d_real)th);
        /* a vector anticommutes with e12, so R a = a R~ and R a R~ = a R~R~ = a q */
        ga2d_mv R = ga2d_mv_from_rotor(ga2d_rotor_from_angle((ga2d_real)(-th / 2)));
        ga2d_rotor q1 = ga2d_rotor_from_angle((ga2d_real)0.5), q2 = ga2d_rotor_from_angle((ga2d_real)0.7);
        ga2d_rotor qab = ga2d_rotor_between(a, b);
        mrow("q = cos(theta) + sin(theta) e12", ga2d_mv_from_rotor(q), c, 0, 0, s);
        vrow("a q  (a turned 30 deg CCW)", ga2d_rotate(q, a), 3 * c - s, 3 * s + c);
        mrow("R a R~, R = exp(-theta e12 / 2)", ga2d_mv_mul(ga2d_mv_mul(R, A), ga2d_mv_reverse(R)),
             0, 3 * c - s, 3 * s + c, 0);
        /* the even subalgebra is the complex numbers: angles add */
        row("angle(q1 q2), angles 0.5 and 0.7", ga2d_rotor_angle(ga2d_rotor_mul(q1, q2)), 1.2);
        row("log q  (e12 coefficient)", ga2d_rotor_log(q).e12, th);
        mrow("exp(log q) = q", ga2d_mv_from_rotor(ga2d_rotor_exp(ga2d_rotor_log(q))), c, 0, 0, s);
        /* ab = a.b + a^b = |a||b| exp(angle e12), normalized */
        row("angle of rotor_between(a, b)", ga2d_rotor_angle(qab), atan2(8.0, 6.0));
        vrow("a q_ab = b  (|a| = |b|)", ga2d_rotate(qab, a), 1, 3);
    }

    /* 5. Mass properties at density 1, so mass = area as in the paper. */
    printf("\n5. Polygons: the paper's right triangle w = 3, h = 2 (Fig. 1), density 1\n");
    {
        ga2d_vec tri[3] = {{0, 0}, {3, 0}, {3, 2}};    /* CCW */
        ga2d_vec cw[3] = {{0, 0}, {3, 2}, {3, 0}};     /* the same, clockwise */
        const double w = 3, h = 2, m = w * h / 2, r3 = sqrt(3.0);
        ga2d_polygon poly, square = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        ga2d_polygon hexagon = ga2d_polygon_regular(6, 1); /* circumradius = side = 1 */
        ga2d_mass mp;
        poly.count = 0; /* "no polygon" until make succeeds: mass refuses it */
        rrow("ga2d_polygon_make(triangle)", ga2d_polygon_make(tri, 3, &poly), GA2D_OK);
        mp = ga2d_polygon_mass(&poly, 1);
        row("area = mass = wh/2", mp.mass, m);
        /* the centroid is the vertex average for a triangle (eqs. 22-23) */
        vrow("centre of mass (2w/3, h/3)  (eq. 22)", mp.center, 2 * w / 3, h / 3);
        /* eq. 26 in closed form: sum of wedges, not numeric integration */
        row("I about centre = m(w^2+h^2)/18", mp.inertia, m * (w * w + h * h) / 18);

        printf("   unit square\n");
        mp = ga2d_polygon_mass(&square, 1);
        row("area", mp.mass, 1);
        vrow("centre of mass", mp.center, 0, 0);
        row("I = (1 + 1)/12", mp.inertia, 1.0 / 6);

        printf("   regular hexagon, side 1\n");
        mp = ga2d_polygon_mass(&hexagon, 1);
        row("area = 3 sqrt(3)/2", mp.mass, 3 * r3 / 2);
        vrow("centre of mass", mp.center, 0, 0);
        row("I = 5 sqrt(3)/8", mp.inertia, 5 * r3 / 8);

        /* eq. 25's area is positive only for CCW winding, so CW is refused */
        printf("   a bad polygon: the triangle wound clockwise\n");
        rrow("ga2d_polygon_make(clockwise)", ga2d_polygon_make(cw, 3, &poly), GA2D_ERR_CLOCKWISE);
    }

    printf("\n%s\n", mismatches ? "SOME VALUES DISAGREE WITH THEIR CLOSED FORMS" : "every value matches its closed form");
    return mismatches ? 1 : 0;
}
