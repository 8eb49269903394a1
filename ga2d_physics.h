/* ga2d_physics.h - v0.1.0 - 2D rigid-body physics of convex polygons,
   written in the geometric algebra of the plane.   MIT / public domain.

   ==========================================================================
   WHAT IT IS
   ==========================================================================
   One header, C99 (compiles unchanged as C++11), libc and libm only.
   This first slice holds the foundation everything else stands on:

     - the geometric algebra G(2,0) of the plane: vectors, bivectors, full
       multivectors with geometric / outer / inner products, and rotors;
     - convex polygons: validated construction, convex hull of a point
       cloud, boxes and regular polygons, transforms and bounding boxes;
     - exact mass properties of a polygon (mass, centre of mass, moment of
       inertia), precise even far from the origin.

   ==========================================================================
   HOW TO USE IT
   ==========================================================================
   Copy this file into your project.  In exactly ONE .c or .cpp file write

       #define GA2D_IMPLEMENTATION
       #include "ga2d_physics.h"

   and include it without the define everywhere else.  Link with -lm.
   Including it a second time with GA2D_IMPLEMENTATION defined adds nothing.

   Config macros (define them before every #include of this file):

     GA2D_DOUBLE               ga2d_real is double (default: float). Every
                               translation unit must agree on it.
     GA2D_STATIC               all functions are static to the file that
                               defines GA2D_IMPLEMENTATION (a private copy).
     GA2D_API                  the linkage of every public function; defaults
                               to extern (static under GA2D_STATIC). Under C++
                               the declarations are extern "C".
     GA2D_ASSERT(c)            internal-invariant check (default assert()).
                               User input is never asserted: it is validated
                               and answered with a ga2d_result.
     GA2D_MAX_POLYGON_VERTICES the most vertices a polygon may have (8).

   Build flags: the library uses no global state.  Do not build it with
   -ffast-math: NaN/Inf checks on user input rely on IEEE semantics.

   ==========================================================================
   THE ALGEBRA, AND ITS CONVENTIONS
   ==========================================================================
   Basis {1, e1, e2, e12} with e1 e1 = e2 e2 = 1 and e12 = e1 e2, so
   e12 e12 = -1 and e1 e12 = e2, e2 e12 = -e1.

     ga2d_vec  {x, y}            = x e1 + y e2
     ga2d_bivec {e12}            = b e12 (an oriented area; angular velocity
                                   Omega = w e12; torque r ^ F)
     ga2d_rotor {c, s}           = c + s e12 = exp(theta e12): a unit element
                                   of the even subalgebra, which is the
                                   complex numbers (e12 plays i).
     ga2d_mv   {s, e1, e2, e12}  = a full multivector.

   a ^ b = (a.x b.y - a.y b.x) e12, and ga2d_wedge(a, b) returns that
   coefficient.  The geometric product of two vectors is ab = a.b + a^b.

   Rotation acts by right multiplication:  v' = v q  turns v
   counter-clockwise by theta.  This is the same as the sandwich R v R~ with
   the half-angle rotor R = exp(-theta e12 / 2), because a vector
   anticommutes with e12:  R v = v R~.  Rotors compose by q1 q2 (commutative
   in the plane).  ga2d_vec_perp(v) = v e12 is v turned by +90 degrees.

     ga2d_vec a = ga2d_vec_make(1, 0);
     ga2d_rotor q = ga2d_rotor_from_angle(0.5f);   // exp(0.5 e12)
     ga2d_vec b = ga2d_rotate(q, a);               // a q = (cos .5, sin .5)
     ga2d_mv  ab = ga2d_vec_mul(a, b);             // a.b + a^b
     ga2d_mv  inv;
     if (ga2d_mv_inverse(ab, &inv) == GA2D_OK) { ... }   // reports 1+e1

   ==========================================================================
   POLYGONS AND MASS
   ==========================================================================
     ga2d_vec pts[4] = {{0,0}, {2,0}, {2,1}, {0,1}};
     ga2d_polygon poly;
     ga2d_result r = ga2d_polygon_make(pts, 4, &poly);   // validates
     if (r != GA2D_OK) printf("%s\n", ga2d_result_string(r));
     ga2d_mass m = ga2d_polygon_mass(&poly, 1.0f);       // density 1
     // m.mass = 2, m.center = (1, 0.5), m.inertia = 2 (4 + 1) / 12

   ga2d_polygon_make wants counter-clockwise, strictly convex vertices and
   names each way input can fail (see ga2d_result).  ga2d_polygon_hull takes
   any point cloud instead.  On failure neither writes its output.

   The mass is exact: area, centroid and inertia are sums of wedges of
   consecutive vertices taken relative to an interior point (the paper's
   eqs. 24-26; I_C = J_r - A |C - r|^2), so a polygon far from the origin
   keeps its precision.

   ==========================================================================
   ERRORS
   ==========================================================================
   Functions that can fail return a ga2d_result (GA2D_OK = 0) and leave
   their outputs untouched on failure; ga2d_result_string() names the code.
   Constructors that return a value (ga2d_polygon_box, ..._regular) return
   a polygon with count 0 for bad input, which every other function refuses.

   ==========================================================================
   VERSION HISTORY
   ==========================================================================
   0.1.0  algebra, polygons, hull, exact mass properties.

   The license is at the end of this file.
*/
#ifndef GA2D_PHYSICS_H
#define GA2D_PHYSICS_H

#include <stddef.h>
#include <stdint.h>

#define GA2D_VERSION_MAJOR 0
#define GA2D_VERSION_MINOR 1
#define GA2D_VERSION_PATCH 0

#ifndef GA2D_MAX_POLYGON_VERTICES
#define GA2D_MAX_POLYGON_VERTICES 8
#endif
#if GA2D_MAX_POLYGON_VERTICES < 3
#error "GA2D_MAX_POLYGON_VERTICES must be at least 3"
#endif

#ifndef GA2D_API
#ifdef GA2D_STATIC
#if defined(__GNUC__) || defined(__clang__)
#define GA2D_API static __attribute__((unused))
#else
#define GA2D_API static
#endif
#else
#define GA2D_API extern
#endif
#endif

#ifdef GA2D_DOUBLE
typedef double ga2d_real;
#else
typedef float ga2d_real;
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- results */
typedef enum ga2d_result {
    GA2D_OK = 0,
    GA2D_ERR_INVALID_ARGUMENT,  /* NULL pointer, negative count, bad enum   */
    GA2D_ERR_NOT_FINITE,        /* a NaN or an infinity in the input        */
    GA2D_ERR_TOO_FEW_POINTS,    /* fewer than 3 (distinct) points           */
    GA2D_ERR_TOO_MANY_POINTS,   /* more than GA2D_MAX_POLYGON_VERTICES      */
    GA2D_ERR_TOO_LARGE,         /* coordinates large enough to overflow     */
    GA2D_ERR_REPEATED_POINTS,   /* two points closer than the tolerance     */
    GA2D_ERR_COLLINEAR_POINTS,  /* a vertex on the line of its neighbours,
                                   or every point on one line               */
    GA2D_ERR_DEGENERATE,        /* zero or near-zero area                   */
    GA2D_ERR_CLOCKWISE,         /* vertices wound clockwise                 */
    GA2D_ERR_NOT_CONVEX,        /* not strictly convex (or self-crossing)   */
    GA2D_ERR_NOT_INVERTIBLE,    /* a multivector with no inverse            */
    GA2D_ERR_OUT_OF_MEMORY,
    GA2D_ERR_STALE_ID,
    GA2D_RESULT_COUNT
} ga2d_result;

GA2D_API const char *ga2d_result_string(ga2d_result r);

/* ---------------------------------------------------------------- algebra */
typedef struct ga2d_vec   { ga2d_real x, y; } ga2d_vec;          /* x e1 + y e2 */
typedef struct ga2d_bivec { ga2d_real e12; } ga2d_bivec;         /* b e12 */
typedef struct ga2d_rotor { ga2d_real c, s; } ga2d_rotor;        /* c + s e12 */
typedef struct ga2d_mv    { ga2d_real s, e1, e2, e12; } ga2d_mv; /* full multivector */

/* vectors */
GA2D_API ga2d_vec  ga2d_vec_make(ga2d_real x, ga2d_real y);
GA2D_API ga2d_vec  ga2d_vec_add(ga2d_vec a, ga2d_vec b);
GA2D_API ga2d_vec  ga2d_vec_sub(ga2d_vec a, ga2d_vec b);
GA2D_API ga2d_vec  ga2d_vec_scale(ga2d_vec v, ga2d_real k);
GA2D_API ga2d_vec  ga2d_vec_neg(ga2d_vec v);
GA2D_API ga2d_real ga2d_dot(ga2d_vec a, ga2d_vec b);          /* a.b */
GA2D_API ga2d_real ga2d_wedge(ga2d_vec a, ga2d_vec b);        /* e12 coefficient of a^b */
GA2D_API ga2d_bivec ga2d_vec_outer(ga2d_vec a, ga2d_vec b);   /* a^b as a bivector */
GA2D_API ga2d_mv   ga2d_vec_mul(ga2d_vec a, ga2d_vec b);      /* ab = a.b + a^b */
GA2D_API ga2d_vec  ga2d_vec_perp(ga2d_vec v);                 /* v e12 = (-y, x) */
GA2D_API ga2d_real ga2d_vec_length(ga2d_vec v);               /* no overflow for huge v */
GA2D_API ga2d_real ga2d_vec_length_sq(ga2d_vec v);
/* Writes v/|v| to *unit and returns |v|.  A zero (or subnormal-small)
   vector is reported by returning 0 and writing the zero vector: it never
   divides by zero.  unit may be NULL. */
GA2D_API ga2d_real ga2d_vec_normalize(ga2d_vec v, ga2d_vec *unit);

/* multivectors */
GA2D_API ga2d_mv   ga2d_mv_make(ga2d_real s, ga2d_real e1, ga2d_real e2, ga2d_real e12);
GA2D_API ga2d_mv   ga2d_mv_from_vec(ga2d_vec v);
GA2D_API ga2d_mv   ga2d_mv_from_bivec(ga2d_bivec b);
GA2D_API ga2d_mv   ga2d_mv_from_rotor(ga2d_rotor q);
GA2D_API ga2d_vec  ga2d_mv_vec_part(ga2d_mv m);               /* grade-1 part as a vector */
GA2D_API ga2d_mv   ga2d_mv_add(ga2d_mv a, ga2d_mv b);
GA2D_API ga2d_mv   ga2d_mv_sub(ga2d_mv a, ga2d_mv b);
GA2D_API ga2d_mv   ga2d_mv_scale(ga2d_mv m, ga2d_real k);
GA2D_API ga2d_mv   ga2d_mv_mul(ga2d_mv a, ga2d_mv b);         /* geometric product */
GA2D_API ga2d_mv   ga2d_mv_outer(ga2d_mv a, ga2d_mv b);       /* a ^ b */
GA2D_API ga2d_mv   ga2d_mv_inner(ga2d_mv a, ga2d_mv b);       /* left contraction a _| b */
GA2D_API ga2d_mv   ga2d_mv_reverse(ga2d_mv m);                /* m~: e12 -> -e12 */
GA2D_API ga2d_mv   ga2d_mv_involute(ga2d_mv m);               /* grade involution: vectors negated */
GA2D_API ga2d_mv   ga2d_mv_conjugate(ga2d_mv m);              /* Clifford conjugate: both */
GA2D_API ga2d_mv   ga2d_mv_grade(ga2d_mv m, int k);           /* <m>_k, k = 0, 1, 2; else 0 */
GA2D_API ga2d_mv   ga2d_mv_dual(ga2d_mv m);                   /* m I^-1, I = e12 */
GA2D_API ga2d_real ga2d_mv_norm(ga2d_mv m);                   /* sqrt(<m m~>_0) */
/* m^-1 = conj(m) / (m conj(m)); m conj(m) = s^2 - e1^2 - e2^2 + e12^2 is a
   scalar.  Where it vanishes (relative to |m|^2: 1 + e1, e1 + e12, ...)
   the input has no inverse: GA2D_ERR_NOT_INVERTIBLE, *out untouched. */
GA2D_API ga2d_result ga2d_mv_inverse(ga2d_mv m, ga2d_mv *out);

/* rotors: unit c + s e12 */
GA2D_API ga2d_rotor ga2d_rotor_identity(void);
GA2D_API ga2d_rotor ga2d_rotor_from_angle(ga2d_real radians);  /* exp(theta e12) */
GA2D_API ga2d_real  ga2d_rotor_angle(ga2d_rotor q);            /* in (-pi, pi] */
GA2D_API ga2d_rotor ga2d_rotor_exp(ga2d_bivec b);              /* exp(b e12) */
GA2D_API ga2d_bivec ga2d_rotor_log(ga2d_rotor q);              /* principal log of a unit rotor */
GA2D_API ga2d_rotor ga2d_rotor_mul(ga2d_rotor a, ga2d_rotor b);/* a b: angles add */
GA2D_API ga2d_rotor ga2d_rotor_inverse(ga2d_rotor q);          /* q~ (= q^-1 for unit q) */
GA2D_API ga2d_vec   ga2d_rotate(ga2d_rotor q, ga2d_vec v);     /* v q: CCW by angle(q) */
GA2D_API ga2d_vec   ga2d_rotate_inv(ga2d_rotor q, ga2d_vec v); /* v q~: CW by angle(q) */
/* q / |q|; the identity for a zero or non-finite q. */
GA2D_API ga2d_rotor ga2d_rotor_normalize(ga2d_rotor q);
/* normalize((1-t) a + t b): follows the shorter arc from a to b; for exactly
   opposite rotors (no shorter arc) it turns counter-clockwise. */
GA2D_API ga2d_rotor ga2d_rotor_nlerp(ga2d_rotor a, ga2d_rotor b, ga2d_real t);
/* the unit rotor q with a^ q = b^ (a^, b^ the directions of a and b):
   q = normalize(a b), since a (a b) = |a|^2 b.  Identity if either is 0. */
GA2D_API ga2d_rotor ga2d_rotor_between(ga2d_vec a, ga2d_vec b);
GA2D_API ga2d_rotor ga2d_rotor_from_mv(ga2d_mv m);             /* even part, normalized */

/* --------------------------------------------------------------- geometry */
typedef struct ga2d_transform { ga2d_vec p; ga2d_rotor q; } ga2d_transform;
typedef struct ga2d_aabb { ga2d_vec lower, upper; } ga2d_aabb;

/* A convex polygon: CCW vertices in its own frame and the outward unit
   normal of edge i (from vertex i to vertex i+1). */
typedef struct ga2d_polygon {
    int count;
    ga2d_vec vertices[GA2D_MAX_POLYGON_VERTICES];
    ga2d_vec normals[GA2D_MAX_POLYGON_VERTICES];
} ga2d_polygon;

/* Mass properties: mass, centre of mass (in the polygon's frame) and the
   moment of inertia about that centre. */
typedef struct ga2d_mass { ga2d_real mass; ga2d_vec center; ga2d_real inertia; } ga2d_mass;

GA2D_API ga2d_transform ga2d_transform_identity(void);
GA2D_API ga2d_transform ga2d_transform_make(ga2d_vec p, ga2d_rotor q);
GA2D_API ga2d_vec ga2d_transform_apply(ga2d_transform x, ga2d_vec v);     /* p + v q */
GA2D_API ga2d_vec ga2d_transform_apply_inv(ga2d_transform x, ga2d_vec v); /* (v - p) q~ */
GA2D_API ga2d_transform ga2d_transform_inverse(ga2d_transform x);
/* a b: first b, then a.  apply(mul(a, b), v) = apply(a, apply(b, v)). */
GA2D_API ga2d_transform ga2d_transform_mul(ga2d_transform a, ga2d_transform b);
/* a^-1 b: b expressed in a's frame, computed without forming a^-1. */
GA2D_API ga2d_transform ga2d_transform_inv_mul(ga2d_transform a, ga2d_transform b);

/* Validates pts[0..n-1] as a strictly convex CCW polygon and fills *out.
   Tolerances scale with the polygon's extent L (the larger side of its
   bounding box): points closer than 64 eps L are repeated, a vertex within
   64 eps L of its neighbours' line is collinear, an area below 1e-5 L^2 is
   degenerate.  Coordinates beyond GA2D_MAX_COORDINATE are too large.
   Checks run in this order, and the first failure is returned:
   INVALID_ARGUMENT, TOO_FEW_POINTS, TOO_MANY_POINTS, NOT_FINITE,
   TOO_LARGE, REPEATED_POINTS, COLLINEAR_POINTS (all on one line),
   DEGENERATE, CLOCKWISE, COLLINEAR_POINTS (one vertex), NOT_CONVEX. */
GA2D_API ga2d_result ga2d_polygon_make(const ga2d_vec *pts, int n, ga2d_polygon *out);
/* The convex hull of any n >= 3 points: near-duplicates welded and points
   on an edge dropped (tolerance 4x that of ga2d_polygon_make), CCW from the
   lowest-x vertex.  Fails with TOO_FEW_POINTS (fewer than 3 distinct
   points), COLLINEAR_POINTS, TOO_MANY_POINTS (the hull has more than
   GA2D_MAX_POLYGON_VERTICES), NOT_FINITE, TOO_LARGE or DEGENERATE.
   Needs no memory beyond the stack: gift wrapping, O(n h). */
GA2D_API ga2d_result ga2d_polygon_hull(const ga2d_vec *pts, int n, ga2d_polygon *out);
/* Axis-aligned box centred on the origin; count 0 if a half-extent is not
   finite and positive. */
GA2D_API ga2d_polygon ga2d_polygon_box(ga2d_real half_width, ga2d_real half_height);
/* Regular n-gon of circumradius r centred on the origin, vertex 0 on +x;
   count 0 if n is outside [3, GA2D_MAX_POLYGON_VERTICES] or r is bad. */
GA2D_API ga2d_polygon ga2d_polygon_regular(int n, ga2d_real radius);
/* AABB of the polygon placed by x. */
GA2D_API ga2d_aabb ga2d_polygon_aabb(const ga2d_polygon *p, ga2d_transform x);
/* Exact mass properties at the given density (mass per unit area).  All
   zero when p is NULL or has a bad count, or density is negative or not
   finite; use ga2d_polygon_mass_checked to be told why. */
GA2D_API ga2d_mass ga2d_polygon_mass(const ga2d_polygon *p, ga2d_real density);
GA2D_API ga2d_result ga2d_polygon_mass_checked(const ga2d_polygon *p, ga2d_real density,
                                               ga2d_mass *out);

/* The largest |coordinate| a polygon vertex may have: inertia grows as the
   4th power of size, and every wedge-sum term below must stay finite with
   room for densities up to ~1e6 (float: (3.4e38 / 1.2e4 / 1e6)^(1/4) ~ 1.2e8;
   double: ~1e75). */
#ifdef GA2D_DOUBLE
#define GA2D_MAX_COORDINATE 1e75
#else
#define GA2D_MAX_COORDINATE 1e8f
#endif

#ifdef __cplusplus
}
#endif
#endif /* GA2D_PHYSICS_H */

/* ======================================================================== */
/*                              IMPLEMENTATION                              */
/* ======================================================================== */
#if defined(GA2D_IMPLEMENTATION) && !defined(GA2D__IMPLEMENTATION_DONE)
#define GA2D__IMPLEMENTATION_DONE

#include <float.h>
#include <math.h>
#include <string.h>

#ifndef GA2D_ASSERT
#include <assert.h>
#define GA2D_ASSERT(c) assert(c)
#endif

#ifdef GA2D_DOUBLE
#define GA2D__EPS DBL_EPSILON
#define GA2D__MIN_NORMAL DBL_MIN
#define GA2D__SQRT(x) sqrt(x)
#define GA2D__SIN(x) sin(x)
#define GA2D__COS(x) cos(x)
#define GA2D__ATAN2(y, x) atan2(y, x)
#define GA2D__FABS(x) fabs(x)
#else
#define GA2D__EPS FLT_EPSILON
#define GA2D__MIN_NORMAL FLT_MIN
#define GA2D__SQRT(x) sqrtf(x)
#define GA2D__SIN(x) sinf(x)
#define GA2D__COS(x) cosf(x)
#define GA2D__ATAN2(y, x) atan2f(y, x)
#define GA2D__FABS(x) fabsf(x)
#endif
#define GA2D__R(x) ((ga2d_real)(x))
#define GA2D__PI GA2D__R(3.14159265358979323846)

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- results */
GA2D_API const char *ga2d_result_string(ga2d_result r)
{
    switch (r) {
    case GA2D_OK: return "ok";
    case GA2D_ERR_INVALID_ARGUMENT: return "invalid argument";
    case GA2D_ERR_NOT_FINITE: return "a value is NaN or infinite";
    case GA2D_ERR_TOO_FEW_POINTS: return "fewer than 3 distinct points";
    case GA2D_ERR_TOO_MANY_POINTS: return "more than GA2D_MAX_POLYGON_VERTICES points";
    case GA2D_ERR_TOO_LARGE: return "coordinates beyond GA2D_MAX_COORDINATE";
    case GA2D_ERR_REPEATED_POINTS: return "two points coincide within the tolerance";
    case GA2D_ERR_COLLINEAR_POINTS: return "points are collinear within the tolerance";
    case GA2D_ERR_DEGENERATE: return "zero or near-zero area";
    case GA2D_ERR_CLOCKWISE: return "vertices are clockwise (want counter-clockwise)";
    case GA2D_ERR_NOT_CONVEX: return "polygon is not strictly convex";
    case GA2D_ERR_NOT_INVERTIBLE: return "multivector is not invertible";
    case GA2D_ERR_OUT_OF_MEMORY: return "out of memory";
    case GA2D_ERR_STALE_ID: return "id is stale or forged";
    case GA2D_RESULT_COUNT: break;
    }
    return "unknown result";
}

static int ga2d__finite(ga2d_real x) { return x - x == x - x; } /* false for NaN, Inf */

/* ---------------------------------------------------------------- vectors */
GA2D_API ga2d_vec ga2d_vec_make(ga2d_real x, ga2d_real y) { ga2d_vec v; v.x = x; v.y = y; return v; }
GA2D_API ga2d_vec ga2d_vec_add(ga2d_vec a, ga2d_vec b) { return ga2d_vec_make(a.x + b.x, a.y + b.y); }
GA2D_API ga2d_vec ga2d_vec_sub(ga2d_vec a, ga2d_vec b) { return ga2d_vec_make(a.x - b.x, a.y - b.y); }
GA2D_API ga2d_vec ga2d_vec_scale(ga2d_vec v, ga2d_real k) { return ga2d_vec_make(v.x * k, v.y * k); }
GA2D_API ga2d_vec ga2d_vec_neg(ga2d_vec v) { return ga2d_vec_make(-v.x, -v.y); }
GA2D_API ga2d_real ga2d_dot(ga2d_vec a, ga2d_vec b) { return a.x * b.x + a.y * b.y; }
GA2D_API ga2d_real ga2d_wedge(ga2d_vec a, ga2d_vec b) { return a.x * b.y - a.y * b.x; }
GA2D_API ga2d_bivec ga2d_vec_outer(ga2d_vec a, ga2d_vec b) { ga2d_bivec r; r.e12 = ga2d_wedge(a, b); return r; }
GA2D_API ga2d_mv ga2d_vec_mul(ga2d_vec a, ga2d_vec b) { return ga2d_mv_make(ga2d_dot(a, b), 0, 0, ga2d_wedge(a, b)); }
/* (x e1 + y e2) e12 = x e2 - y e1 */
GA2D_API ga2d_vec ga2d_vec_perp(ga2d_vec v) { return ga2d_vec_make(-v.y, v.x); }
GA2D_API ga2d_real ga2d_vec_length_sq(ga2d_vec v) { return v.x * v.x + v.y * v.y; }

/* Scale by the larger component first so |v|^2 neither overflows (1e30 in
   float) nor underflows to zero (1e-30). */
GA2D_API ga2d_real ga2d_vec_length(ga2d_vec v)
{
    ga2d_real ax = GA2D__FABS(v.x), ay = GA2D__FABS(v.y);
    ga2d_real m = ax > ay ? ax : ay, u, w;
    if (!(m > 0)) return ax + ay; /* 0, or NaN passed through */
    if (!ga2d__finite(m)) return m;
    u = ax / m;
    w = ay / m;
    return m * GA2D__SQRT(u * u + w * w);
}

GA2D_API ga2d_real ga2d_vec_normalize(ga2d_vec v, ga2d_vec *unit)
{
    ga2d_real len = ga2d_vec_length(v);
    ga2d_vec u = ga2d_vec_make(0, 0);
    /* below the smallest normal number 1/len would overflow: report zero */
    if (!(len >= GA2D__MIN_NORMAL) || !ga2d__finite(len)) len = 0;
    else u = ga2d_vec_make(v.x / len, v.y / len);
    if (unit) *unit = u;
    return len;
}

/* ----------------------------------------------------------- multivectors */
GA2D_API ga2d_mv ga2d_mv_make(ga2d_real s, ga2d_real e1, ga2d_real e2, ga2d_real e12)
{
    ga2d_mv m;
    m.s = s; m.e1 = e1; m.e2 = e2; m.e12 = e12;
    return m;
}
GA2D_API ga2d_mv ga2d_mv_from_vec(ga2d_vec v) { return ga2d_mv_make(0, v.x, v.y, 0); }
GA2D_API ga2d_mv ga2d_mv_from_bivec(ga2d_bivec b) { return ga2d_mv_make(0, 0, 0, b.e12); }
GA2D_API ga2d_mv ga2d_mv_from_rotor(ga2d_rotor q) { return ga2d_mv_make(q.c, 0, 0, q.s); }
GA2D_API ga2d_vec ga2d_mv_vec_part(ga2d_mv m) { return ga2d_vec_make(m.e1, m.e2); }
GA2D_API ga2d_mv ga2d_mv_add(ga2d_mv a, ga2d_mv b) { return ga2d_mv_make(a.s + b.s, a.e1 + b.e1, a.e2 + b.e2, a.e12 + b.e12); }
GA2D_API ga2d_mv ga2d_mv_sub(ga2d_mv a, ga2d_mv b) { return ga2d_mv_make(a.s - b.s, a.e1 - b.e1, a.e2 - b.e2, a.e12 - b.e12); }
GA2D_API ga2d_mv ga2d_mv_scale(ga2d_mv m, ga2d_real k) { return ga2d_mv_make(m.s * k, m.e1 * k, m.e2 * k, m.e12 * k); }

/* The full product table of G(2,0): e1e1 = e2e2 = 1, e1e2 = -e2e1 = e12,
   e12e12 = -1, e1e12 = e2, e12e1 = -e2, e2e12 = -e1, e12e2 = e1. */
GA2D_API ga2d_mv ga2d_mv_mul(ga2d_mv a, ga2d_mv b)
{
    return ga2d_mv_make(a.s * b.s + a.e1 * b.e1 + a.e2 * b.e2 - a.e12 * b.e12,
                        a.s * b.e1 + a.e1 * b.s - a.e2 * b.e12 + a.e12 * b.e2,
                        a.s * b.e2 + a.e2 * b.s + a.e1 * b.e12 - a.e12 * b.e1,
                        a.s * b.e12 + a.e12 * b.s + a.e1 * b.e2 - a.e2 * b.e1);
}

/* Outer product: the part of each blade product whose grade is the sum of
   the factors' grades. */
GA2D_API ga2d_mv ga2d_mv_outer(ga2d_mv a, ga2d_mv b)
{
    return ga2d_mv_make(a.s * b.s,
                        a.s * b.e1 + a.e1 * b.s,
                        a.s * b.e2 + a.e2 * b.s,
                        a.s * b.e12 + a.e12 * b.s + a.e1 * b.e2 - a.e2 * b.e1);
}

/* Left contraction: the part of each blade product whose grade is
   grade(b) - grade(a) (zero where that is negative).  For vectors it is
   the dot product, and a _| B "collapses" B along a (the paper's eq. 3). */
GA2D_API ga2d_mv ga2d_mv_inner(ga2d_mv a, ga2d_mv b)
{
    return ga2d_mv_make(a.s * b.s + a.e1 * b.e1 + a.e2 * b.e2 - a.e12 * b.e12,
                        a.s * b.e1 - a.e2 * b.e12,
                        a.s * b.e2 + a.e1 * b.e12,
                        a.s * b.e12);
}

GA2D_API ga2d_mv ga2d_mv_reverse(ga2d_mv m) { return ga2d_mv_make(m.s, m.e1, m.e2, -m.e12); }
GA2D_API ga2d_mv ga2d_mv_involute(ga2d_mv m) { return ga2d_mv_make(m.s, -m.e1, -m.e2, m.e12); }
GA2D_API ga2d_mv ga2d_mv_conjugate(ga2d_mv m) { return ga2d_mv_make(m.s, -m.e1, -m.e2, -m.e12); }

GA2D_API ga2d_mv ga2d_mv_grade(ga2d_mv m, int k)
{
    switch (k) {
    case 0: return ga2d_mv_make(m.s, 0, 0, 0);
    case 1: return ga2d_mv_make(0, m.e1, m.e2, 0);
    case 2: return ga2d_mv_make(0, 0, 0, m.e12);
    default: return ga2d_mv_make(0, 0, 0, 0);
    }
}

/* m I^-1 with I^-1 = -e12: 1 -> -e12, e1 -> -e2, e2 -> e1, e12 -> 1. */
GA2D_API ga2d_mv ga2d_mv_dual(ga2d_mv m) { return ga2d_mv_make(m.e12, m.e2, -m.e1, -m.s); }

/* <m m~>_0 is the sum of the squared coefficients (e12 e12~ = 1). */
GA2D_API ga2d_real ga2d_mv_norm(ga2d_mv m)
{
    return ga2d_vec_length(ga2d_vec_make(ga2d_vec_length(ga2d_vec_make(m.s, m.e1)),
                                         ga2d_vec_length(ga2d_vec_make(m.e2, m.e12))));
}

GA2D_API ga2d_result ga2d_mv_inverse(ga2d_mv m, ga2d_mv *out)
{
    ga2d_real n2, det;
    if (!out) return GA2D_ERR_INVALID_ARGUMENT;
    if (!ga2d__finite(m.s) || !ga2d__finite(m.e1) || !ga2d__finite(m.e2) || !ga2d__finite(m.e12))
        return GA2D_ERR_NOT_FINITE;
    n2 = m.s * m.s + m.e1 * m.e1 + m.e2 * m.e2 + m.e12 * m.e12;
    det = m.s * m.s - m.e1 * m.e1 - m.e2 * m.e2 + m.e12 * m.e12;
    /* det is a difference of sums of squares; its rounding error is a few
       eps n2, so anything smaller cannot be told from zero. */
    if (!ga2d__finite(n2) || !(GA2D__FABS(det) > 8 * GA2D__EPS * n2) ||
        !(GA2D__FABS(det) >= GA2D__MIN_NORMAL))
        return GA2D_ERR_NOT_INVERTIBLE;
    *out = ga2d_mv_scale(ga2d_mv_conjugate(m), 1 / det);
    return GA2D_OK;
}

/* ---------------------------------------------------------------- rotors */
static ga2d_rotor ga2d__rotor(ga2d_real c, ga2d_real s) { ga2d_rotor q; q.c = c; q.s = s; return q; }
GA2D_API ga2d_rotor ga2d_rotor_identity(void) { return ga2d__rotor(1, 0); }
GA2D_API ga2d_rotor ga2d_rotor_from_angle(ga2d_real t) { return ga2d__rotor(GA2D__COS(t), GA2D__SIN(t)); }
GA2D_API ga2d_real ga2d_rotor_angle(ga2d_rotor q) { return GA2D__ATAN2(q.s, q.c); }
/* exp(b e12) = cos b + sin b e12, because (e12)^2 = -1 (Euler's formula). */
GA2D_API ga2d_rotor ga2d_rotor_exp(ga2d_bivec b) { return ga2d_rotor_from_angle(b.e12); }
GA2D_API ga2d_bivec ga2d_rotor_log(ga2d_rotor q) { ga2d_bivec b; b.e12 = ga2d_rotor_angle(q); return b; }
GA2D_API ga2d_rotor ga2d_rotor_mul(ga2d_rotor a, ga2d_rotor b)
{
    return ga2d__rotor(a.c * b.c - a.s * b.s, a.c * b.s + a.s * b.c);
}
GA2D_API ga2d_rotor ga2d_rotor_inverse(ga2d_rotor q) { return ga2d__rotor(q.c, -q.s); }
/* (x e1 + y e2)(c + s e12) = (c x - s y) e1 + (s x + c y) e2 */
GA2D_API ga2d_vec ga2d_rotate(ga2d_rotor q, ga2d_vec v)
{
    return ga2d_vec_make(q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y);
}
GA2D_API ga2d_vec ga2d_rotate_inv(ga2d_rotor q, ga2d_vec v)
{
    return ga2d_vec_make(q.c * v.x + q.s * v.y, q.c * v.y - q.s * v.x);
}
GA2D_API ga2d_rotor ga2d_rotor_normalize(ga2d_rotor q)
{
    ga2d_vec u;
    if (ga2d_vec_normalize(ga2d_vec_make(q.c, q.s), &u) == 0) return ga2d_rotor_identity();
    return ga2d__rotor(u.x, u.y);
}
GA2D_API ga2d_rotor ga2d_rotor_nlerp(ga2d_rotor a, ga2d_rotor b, ga2d_real t)
{
    ga2d_vec u;
    ga2d_real len = ga2d_vec_normalize(ga2d_vec_make((1 - t) * a.c + t * b.c, (1 - t) * a.s + t * b.s), &u);
    /* v q is not double-covered: q and -q are rotations half a turn apart,
       so the chord between them passes through zero.  Take the CCW arc. */
    if (len <= 4 * GA2D__EPS) return ga2d_rotor_mul(a, ga2d_rotor_from_angle(t * GA2D__PI));
    return ga2d__rotor(u.x, u.y);
}
GA2D_API ga2d_rotor ga2d_rotor_between(ga2d_vec a, ga2d_vec b)
{
    ga2d_vec ua, ub;
    if (ga2d_vec_normalize(a, &ua) == 0 || ga2d_vec_normalize(b, &ub) == 0) return ga2d_rotor_identity();
    return ga2d_rotor_normalize(ga2d__rotor(ga2d_dot(ua, ub), ga2d_wedge(ua, ub)));
}
GA2D_API ga2d_rotor ga2d_rotor_from_mv(ga2d_mv m) { return ga2d_rotor_normalize(ga2d__rotor(m.s, m.e12)); }

/* ------------------------------------------------------------- transforms */
GA2D_API ga2d_transform ga2d_transform_make(ga2d_vec p, ga2d_rotor q) { ga2d_transform x; x.p = p; x.q = q; return x; }
GA2D_API ga2d_transform ga2d_transform_identity(void) { return ga2d_transform_make(ga2d_vec_make(0, 0), ga2d_rotor_identity()); }
GA2D_API ga2d_vec ga2d_transform_apply(ga2d_transform x, ga2d_vec v) { return ga2d_vec_add(x.p, ga2d_rotate(x.q, v)); }
GA2D_API ga2d_vec ga2d_transform_apply_inv(ga2d_transform x, ga2d_vec v) { return ga2d_rotate_inv(x.q, ga2d_vec_sub(v, x.p)); }
GA2D_API ga2d_transform ga2d_transform_inverse(ga2d_transform x)
{
    return ga2d_transform_make(ga2d_rotate_inv(x.q, ga2d_vec_neg(x.p)), ga2d_rotor_inverse(x.q));
}
GA2D_API ga2d_transform ga2d_transform_mul(ga2d_transform a, ga2d_transform b)
{
    return ga2d_transform_make(ga2d_transform_apply(a, b.p), ga2d_rotor_mul(a.q, b.q));
}
GA2D_API ga2d_transform ga2d_transform_inv_mul(ga2d_transform a, ga2d_transform b)
{
    return ga2d_transform_make(ga2d_transform_apply_inv(a, b.p), ga2d_rotor_mul(ga2d_rotor_inverse(a.q), b.q));
}

/* --------------------------------------------------------------- polygons */
/* Relative tolerances of polygon validation.  Rounding in a wedge of two
   edges of length <= L is a few eps L^2, so 64 eps L is the smallest gap
   that arithmetic can tell from zero with a margin; below an area of
   1e-5 L^2 (a 1 m x 10 um needle) no contact solver can hold the shape. */
#define GA2D__POLY_REL_TOL (64 * GA2D__EPS)
#define GA2D__POLY_MIN_AREA_RATIO GA2D__R(1e-5)

/* Checks shared by make and hull: counts, finiteness, size.  Reports the
   extent L (the larger bounding-box side) through *extent. */
static ga2d_result ga2d__check_points(const ga2d_vec *pts, int n, ga2d_real *extent)
{
    int i;
    ga2d_vec lo, hi;
    if (n < 3) return GA2D_ERR_TOO_FEW_POINTS;
    for (i = 0; i < n; ++i)
        if (!ga2d__finite(pts[i].x) || !ga2d__finite(pts[i].y)) return GA2D_ERR_NOT_FINITE;
    for (i = 0; i < n; ++i)
        if (GA2D__FABS(pts[i].x) > GA2D_MAX_COORDINATE || GA2D__FABS(pts[i].y) > GA2D_MAX_COORDINATE)
            return GA2D_ERR_TOO_LARGE;
    lo = hi = pts[0];
    for (i = 1; i < n; ++i) {
        lo.x = pts[i].x < lo.x ? pts[i].x : lo.x;
        lo.y = pts[i].y < lo.y ? pts[i].y : lo.y;
        hi.x = pts[i].x > hi.x ? pts[i].x : hi.x;
        hi.y = pts[i].y > hi.y ? pts[i].y : hi.y;
    }
    *extent = (hi.x - lo.x) > (hi.y - lo.y) ? hi.x - lo.x : hi.y - lo.y;
    return GA2D_OK;
}

/* Distance of p from the line through a and b (b != a). */
static ga2d_real ga2d__line_distance(ga2d_vec a, ga2d_vec b, ga2d_vec p)
{
    ga2d_vec ab = ga2d_vec_sub(b, a);
    return GA2D__FABS(ga2d_wedge(ab, ga2d_vec_sub(p, a))) / ga2d_vec_length(ab);
}

/* Do all points lie within tol of the line through the two farthest apart? */
static int ga2d__all_collinear(const ga2d_vec *pts, int n, ga2d_real tol)
{
    int i, j, a = 0, b = 1;
    ga2d_real best = -1;
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j) {
            ga2d_real d = ga2d_vec_length_sq(ga2d_vec_sub(pts[j], pts[i]));
            if (d > best) { best = d; a = i; b = j; }
        }
    for (i = 0; i < n; ++i)
        if (ga2d__line_distance(pts[a], pts[b], pts[i]) > tol) return 0;
    return 1;
}

/* Twice the signed area, as wedges relative to pts[0] so that a polygon far
   from the origin loses nothing (the paper's eq. 25 with C = pts[0]). */
static ga2d_real ga2d__twice_area(const ga2d_vec *pts, int n)
{
    ga2d_real sum = 0;
    int i;
    for (i = 1; i + 1 < n; ++i) sum += ga2d_wedge(ga2d_vec_sub(pts[i], pts[0]), ga2d_vec_sub(pts[i + 1], pts[0]));
    return sum;
}

/* Every vertex other than the edge's own two lies strictly left of every
   edge.  For a CCW loop this is exactly strict convexity and simplicity. */
static int ga2d__strictly_convex(const ga2d_vec *pts, int n, ga2d_real tol)
{
    int i, j;
    for (i = 0; i < n; ++i) {
        ga2d_vec a = pts[i], e = ga2d_vec_sub(pts[(i + 1) % n], a);
        ga2d_real len = ga2d_vec_length(e);
        for (j = 0; j < n; ++j) {
            if (j == i || j == (i + 1) % n) continue;
            if (!(ga2d_wedge(e, ga2d_vec_sub(pts[j], a)) > tol * len)) return 0;
        }
    }
    return 1;
}

GA2D_API ga2d_result ga2d_polygon_make(const ga2d_vec *pts, int n, ga2d_polygon *out)
{
    ga2d_polygon poly;
    ga2d_real L, tol, area2;
    ga2d_result r;
    int i, j;
    if (!out || (n > 0 && !pts) || n < 0) return GA2D_ERR_INVALID_ARGUMENT;
    if (n < 3) return GA2D_ERR_TOO_FEW_POINTS;
    if (n > GA2D_MAX_POLYGON_VERTICES) return GA2D_ERR_TOO_MANY_POINTS;
    r = ga2d__check_points(pts, n, &L);
    if (r != GA2D_OK) return r;
    tol = GA2D__POLY_REL_TOL * L;
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j)
            if (ga2d_vec_length(ga2d_vec_sub(pts[j], pts[i])) <= tol) return GA2D_ERR_REPEATED_POINTS;
    if (ga2d__all_collinear(pts, n, tol)) return GA2D_ERR_COLLINEAR_POINTS;
    area2 = ga2d__twice_area(pts, n);
    if (GA2D__FABS(area2) <= 2 * GA2D__POLY_MIN_AREA_RATIO * L * L) return GA2D_ERR_DEGENERATE;
    if (area2 < 0) return GA2D_ERR_CLOCKWISE;
    for (i = 0; i < n; ++i)
        if (ga2d__line_distance(pts[(i + n - 1) % n], pts[(i + 1) % n], pts[i]) <= tol)
            return GA2D_ERR_COLLINEAR_POINTS;
    if (!ga2d__strictly_convex(pts, n, tol)) return GA2D_ERR_NOT_CONVEX;

    memset(&poly, 0, sizeof poly);
    poly.count = n;
    for (i = 0; i < n; ++i) {
        ga2d_vec e = ga2d_vec_sub(pts[(i + 1) % n], pts[i]);
        poly.vertices[i] = pts[i];
        /* outward normal of a CCW edge: e turned clockwise, -(e e12) */
        ga2d_vec_normalize(ga2d_vec_make(e.y, -e.x), &poly.normals[i]);
    }
    *out = poly;
    return GA2D_OK;
}

/* One gift-wrapping step from p: the point q such that no point lies
   clearly right of p->q.  Points within tol of p are welded to it; among
   points within tol of the line p->q the farthest wins, so points on an
   edge are dropped.  -1 if every point welds to p. */
static int ga2d__hull_next(const ga2d_vec *pts, int n, ga2d_vec p, ga2d_real tol)
{
    int q = -1, r;
    ga2d_vec dq = ga2d_vec_make(0, 0);
    ga2d_real lq = 0;
    for (r = 0; r < n; ++r) {
        ga2d_vec d = ga2d_vec_sub(pts[r], p);
        ga2d_real lr = ga2d_vec_length(d), w;
        if (lr <= tol) continue;
        if (q < 0) { q = r; dq = d; lq = lr; continue; }
        w = ga2d_wedge(dq, d); /* < 0: r is right of p->q */
        if (w < -tol * lq || (w <= tol * lq && lr > lq)) { q = r; dq = d; lq = lr; }
    }
    return q;
}

GA2D_API ga2d_result ga2d_polygon_hull(const ga2d_vec *pts, int n, ga2d_polygon *out)
{
    enum { CAP = GA2D_MAX_POLYGON_VERTICES + 2 };
    ga2d_vec hull[CAP];
    ga2d_real L, tol;
    ga2d_result r;
    int i, h = 0, start = 0, p, steps;
    if (!out || (n > 0 && !pts) || n < 0) return GA2D_ERR_INVALID_ARGUMENT;
    r = ga2d__check_points(pts, n, &L);
    if (r != GA2D_OK) return r;
    tol = 4 * GA2D__POLY_REL_TOL * L;
    for (i = 1; i < n; ++i)
        if (pts[i].x < pts[start].x || (pts[i].x == pts[start].x && pts[i].y < pts[start].y)) start = i;
    hull[h++] = pts[start];
    p = start;
    for (steps = 0;; ++steps) {
        int q = ga2d__hull_next(pts, n, pts[p], tol);
        if (q < 0) return GA2D_ERR_TOO_FEW_POINTS; /* all points are one */
        if (q == start || ga2d_vec_length(ga2d_vec_sub(pts[q], pts[start])) <= tol) break;
        if (h == CAP) return GA2D_ERR_TOO_MANY_POINTS;
        /* exact arithmetic closes the loop within n steps; rounding that
           does not is a cloud too thin to wrap */
        if (steps > n) return GA2D_ERR_DEGENERATE;
        hull[h++] = pts[q];
        p = q;
    }
    if (h == 2) {
        /* a segment: a third distinct point makes the cloud collinear */
        for (i = 0; i < n; ++i)
            if (ga2d_vec_length(ga2d_vec_sub(pts[i], hull[0])) > tol &&
                ga2d_vec_length(ga2d_vec_sub(pts[i], hull[1])) > tol)
                return GA2D_ERR_COLLINEAR_POINTS;
        return GA2D_ERR_TOO_FEW_POINTS;
    }
    /* drop any vertex the wrap left within tol of its neighbours' line */
    for (i = 0; h > 3 && i < h;) {
        if (ga2d__line_distance(hull[(i + h - 1) % h], hull[(i + 1) % h], hull[i]) <= tol) {
            memmove(&hull[i], &hull[i + 1], (size_t)(h - i - 1) * sizeof hull[0]);
            --h;
            i = 0;
        } else {
            ++i;
        }
    }
    if (h > GA2D_MAX_POLYGON_VERTICES) return GA2D_ERR_TOO_MANY_POINTS;
    return ga2d_polygon_make(hull, h, out);
}

GA2D_API ga2d_polygon ga2d_polygon_box(ga2d_real hw, ga2d_real hh)
{
    ga2d_polygon poly;
    memset(&poly, 0, sizeof poly);
    if (!(hw > 0 && hh > 0 && hw <= GA2D_MAX_COORDINATE && hh <= GA2D_MAX_COORDINATE)) return poly;
    poly.count = 4;
    poly.vertices[0] = ga2d_vec_make(-hw, -hh);
    poly.vertices[1] = ga2d_vec_make(hw, -hh);
    poly.vertices[2] = ga2d_vec_make(hw, hh);
    poly.vertices[3] = ga2d_vec_make(-hw, hh);
    poly.normals[0] = ga2d_vec_make(0, -1);
    poly.normals[1] = ga2d_vec_make(1, 0);
    poly.normals[2] = ga2d_vec_make(0, 1);
    poly.normals[3] = ga2d_vec_make(-1, 0);
    return poly;
}

GA2D_API ga2d_polygon ga2d_polygon_regular(int n, ga2d_real radius)
{
    ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES];
    ga2d_polygon poly;
    int i;
    memset(&poly, 0, sizeof poly);
    if (n < 3 || n > GA2D_MAX_POLYGON_VERTICES || !(radius > 0)) return poly;
    for (i = 0; i < n; ++i) {
        /* angles from double, so float builds place vertices as well as
           float can hold them */
        double t = 2.0 * 3.14159265358979323846 * (double)i / (double)n;
        pts[i] = ga2d_vec_make(radius * (ga2d_real)cos(t), radius * (ga2d_real)sin(t));
    }
    if (ga2d_polygon_make(pts, n, &poly) != GA2D_OK) poly.count = 0;
    return poly;
}

GA2D_API ga2d_aabb ga2d_polygon_aabb(const ga2d_polygon *p, ga2d_transform x)
{
    ga2d_aabb box;
    int i;
    box.lower = box.upper = x.p;
    if (!p || p->count < 1 || p->count > GA2D_MAX_POLYGON_VERTICES) return box;
    box.lower = box.upper = ga2d_transform_apply(x, p->vertices[0]);
    for (i = 1; i < p->count; ++i) {
        ga2d_vec v = ga2d_transform_apply(x, p->vertices[i]);
        box.lower.x = v.x < box.lower.x ? v.x : box.lower.x;
        box.lower.y = v.y < box.lower.y ? v.y : box.lower.y;
        box.upper.x = v.x > box.upper.x ? v.x : box.upper.x;
        box.upper.y = v.y > box.upper.y ? v.y : box.upper.y;
    }
    return box;
}

/* ----------------------------------------------------------- mass (exact) */
/* Fan the polygon into triangles (r, x_i, x_i+1) about the interior point r
   (the vertex mean).  With d_i = x_i - r and c_i = d_i ^ d_i+1 (twice the
   triangle's signed area):
     A   = 1/2 sum c_i                                   (paper eq. 25)
     C-r = sum c_i (d_i + d_i+1) / (6 A)                 (eq. 24: moments of
                                                          the triangles)
     J_r = sum c_i (d_i.d_i + d_i.d_i+1 + d_i+1.d_i+1) / 12   (eq. 26 exact)
     I_C = J_r - A |C - r|^2                             (parallel axes)
   Every d_i is small even when the polygon is far from the origin, so no
   term is a large number minus a large number. */
GA2D_API ga2d_result ga2d_polygon_mass_checked(const ga2d_polygon *p, ga2d_real density, ga2d_mass *out)
{
    ga2d_vec ref = ga2d_vec_make(0, 0), moment = ga2d_vec_make(0, 0), rel;
    ga2d_real area2 = 0, j12 = 0, area, inertia;
    ga2d_mass m;
    int i, n;
    if (!p || !out) return GA2D_ERR_INVALID_ARGUMENT;
    n = p->count;
    if (n < 3) return GA2D_ERR_TOO_FEW_POINTS;
    if (n > GA2D_MAX_POLYGON_VERTICES) return GA2D_ERR_TOO_MANY_POINTS;
    if (!ga2d__finite(density)) return GA2D_ERR_NOT_FINITE;
    if (density < 0) return GA2D_ERR_INVALID_ARGUMENT;
    for (i = 0; i < n; ++i) ref = ga2d_vec_add(ref, ga2d_vec_scale(p->vertices[i], 1 / (ga2d_real)n));
    for (i = 0; i < n; ++i) {
        ga2d_vec d0 = ga2d_vec_sub(p->vertices[i], ref);
        ga2d_vec d1 = ga2d_vec_sub(p->vertices[(i + 1) % n], ref);
        ga2d_real c = ga2d_wedge(d0, d1);
        area2 += c;
        moment = ga2d_vec_add(moment, ga2d_vec_scale(ga2d_vec_add(d0, d1), c));
        j12 += c * (ga2d_dot(d0, d0) + ga2d_dot(d0, d1) + ga2d_dot(d1, d1));
    }
    if (!(area2 > 0)) return GA2D_ERR_DEGENERATE;
    area = area2 / 2;
    rel = ga2d_vec_scale(moment, 1 / (3 * area2));
    inertia = j12 / 12 - area * ga2d_vec_length_sq(rel);
    m.mass = density * area;
    m.center = ga2d_vec_add(ref, rel);
    m.inertia = density * inertia;
    if (!ga2d__finite(m.mass) || !ga2d__finite(m.inertia) || !ga2d__finite(m.center.x) || !ga2d__finite(m.center.y))
        return GA2D_ERR_TOO_LARGE;
    *out = m;
    return GA2D_OK;
}

GA2D_API ga2d_mass ga2d_polygon_mass(const ga2d_polygon *p, ga2d_real density)
{
    ga2d_mass m;
    memset(&m, 0, sizeof m);
    if (ga2d_polygon_mass_checked(p, density, &m) != GA2D_OK) memset(&m, 0, sizeof m);
    return m;
}

#ifdef __cplusplus
}
#endif
#endif /* GA2D_IMPLEMENTATION */

/*
------------------------------------------------------------------------------
This software is available under 2 licenses -- choose whichever you prefer.
------------------------------------------------------------------------------
ALTERNATIVE A - MIT License
Copyright (c) 2026 the ga2d_physics authors
Permission is hereby granted, free of charge, to any person obtaining a copy of
this software and associated documentation files (the "Software"), to deal in
the Software without restriction, including without limitation the rights to
use, copy, modify, merge, publish, distribute, sublicense, and/or sell copies
of the Software, and to permit persons to whom the Software is furnished to do
so, subject to the following conditions:
The above copyright notice and this permission notice shall be included in all
copies or substantial portions of the Software.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
SOFTWARE.
------------------------------------------------------------------------------
ALTERNATIVE B - Public Domain (www.unlicense.org)
This is free and unencumbered software released into the public domain.
Anyone is free to copy, modify, publish, use, compile, sell, or distribute this
software, either in source code form or as a compiled binary, for any purpose,
commercial or non-commercial, and by any means.
In jurisdictions that recognize copyright laws, the author or authors of this
software dedicate any and all copyright interest in the software to the public
domain. We make this dedication for the benefit of the public at large and to
the detriment of our heirs and successors. We intend this dedication to be an
overt act of relinquishment in perpetuity of all present and future rights to
this software under copyright law.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
SOFTWARE.
------------------------------------------------------------------------------
*/
