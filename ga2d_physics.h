/* ga2d_physics.h - v0.9.0 - 2D rigid-body physics of circles, capsules,
   polygons, segments and chains, written in the geometric algebra of the
   plane.   MIT / public domain.

   ==========================================================================
   WHAT IT IS
   ==========================================================================
   One header, C99 (compiles unchanged as C++11), libc and libm only.
   What it holds:

     - the geometric algebra G(2,0) of the plane: vectors, bivectors, full
       multivectors with geometric / outer / inner products, and rotors;
     - shapes: circles, capsules, convex polygons (validated, with a
       convex hull of a point cloud, boxes and regular polygons) with an
       optional radius, segments and one-sided chains; bodies of any
       number of them;
     - exact mass properties of every shape and of a body as their sum
       (mass, centre of mass, moment of inertia), precise even far from
       the origin;
     - a world of static, kinematic and dynamic bodies moving under
       gravity, forces, torques, impulses and a user force field, with a
       choice of integrator and rotor update;
     - collision detection: manifolds for every pair of shapes (usable
       alone, without a world) and a broadphase of dynamic AABB trees that
       keeps the world's contact list, with begin/end and hit events,
       filtering, sensors and a pre-solve callback;
     - a contact solver (soft step by default; PGS with Baumgarte or NGS
       selectable) with friction, rolling, conveyor belts, rolling
       resistance, restitution and islands that sleep.

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
     GA2D_NO_SIMD              the solver's lanes as plain structs, not gcc
                               or clang vectors (the same bits either way;
                               compilers other than gcc and clang always
                               use the structs).  With -mavx (-march=native
                               on most x86-64) the lanes are 32 bytes wide.

   Build flags: the library uses no global state.  Do not build it with
   -ffast-math: NaN/Inf checks on user input rely on IEEE semantics.  Build
   with -ffp-contract=off (as the Makefile does) for results that do not
   depend on the compiler's use of fused multiply-add.

   Determinism: with those flags a step gives the same bits under gcc and
   clang, as C or C++, at any -O level (make test checks -O0/-O2/-O3), run
   after run, and whatever bodies are made and destroyed elsewhere in the
   world: the solver's order is canonical (body slots, then contact age),
   never the contact pool's.  The step calls no libm function whose result
   may differ between platforms (only sqrt, which IEEE rounds exactly; the
   rotor update uses the library's own series).  Float and double builds
   each have their own bits.

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
   THE WORLD AND ITS BODIES
   ==========================================================================
     ga2d_world_def wd = ga2d_default_world_def();   // gravity (0,-10), 4 substeps
     ga2d_world *world = ga2d_world_create(&wd);     // NULL on failure

     ga2d_body_def bd = ga2d_default_body_def();     // static, no shape
     bd.type = GA2D_BODY_DYNAMIC;
     bd.position = ga2d_vec_make(0, 4);
     bd.polygon = ga2d_polygon_box(0.5f, 0.25f);     // its first shape
     ga2d_body_id box = ga2d_body_create(world, &bd); // null id on failure

     ga2d_body_def bd2 = ga2d_default_body_def();    // a ball: shapes by hand
     bd2.type = GA2D_BODY_DYNAMIC;
     ga2d_body_id ball = ga2d_body_create(world, &bd2);
     ga2d_shape_def sd = ga2d_default_shape_def();   // density, friction, filter
     ga2d_circle disc = {{0, 0}, 0.25f};
     ga2d_shape_create_circle(world, ball, &sd, &disc);

     for (int i = 0; i < 60; ++i) ga2d_world_step(world, 1.0f / 60);
     ga2d_vec p = ga2d_body_position(world, box);    // the body origin
     ga2d_world_destroy(world);

   A body's state lives at its centre of mass: ga2d_body_center and
   ga2d_body_velocity are the centre's; ga2d_body_position is the origin its
   polygon's vertices are given in.  Orientation is a rotor; angular
   velocity is the bivector Omega = w e12 (ga2d_body_angular_velocity
   returns w).  A body point at offset r from the centre moves with
   v + r Omega; a force F at r gives the torque r ^ F.

   Ids carry a generation: a destroyed body's id is refused everywhere
   (GA2D_ERR_STALE_ID), also once its slot is reused.  The world has no
   global state; its memory comes from ga2d_world_def.allocator.

   Integrators (ga2d_world_def.integrator), per substep h = dt / substeps:
     GA2D_INTEGRATOR_SYMPLECTIC_EULER  v += h a(x); x += h v.  1st order,
         symplectic (energy error bounded, no drift), 1 force evaluation.
     GA2D_INTEGRATOR_VERLET  kick h/2, drift h, kick h/2.  2nd order,
         symplectic, exact under constant forces; forces must depend on
         position only; 1 evaluation (the end of a step starts the next).
     GA2D_INTEGRATOR_RK4  classic Runge-Kutta.  4th order, 4 evaluations,
         not symplectic (slow energy drift).
   Rotor update (ga2d_world_def.rotation_update): GA2D_ROTATION_EXACT turns
   by q <- q exp(w h e12) (its own series: no libm in the step);
   GA2D_ROTATION_LINEAR by normalize(q (1 + w h e12)), cheaper, lagging by
   w h - atan(w h) per substep.  Bodies that do not turn skip it.

   A force field is a callback (ga2d_world_def.force_callback): the step
   calls it at every state its integrator needs; inside, the getters read
   that state and ga2d_body_apply_force adds to it:

     static void spring(ga2d_world *w, void *ctx) {
         ga2d_body_id id = *(ga2d_body_id *)ctx;
         ga2d_vec x = ga2d_body_center(w, id);
         ga2d_body_apply_force_to_center(w, id, ga2d_vec_scale(x, -40.0f));
     }

   ==========================================================================
   COLLISION
   ==========================================================================
     ga2d_manifold m;
     int n = ga2d_collide_polygons(&poly_a, xa, &poly_b, xb, &m);
     // n points (0, 1 or 2); m.normal is unit, from A to B;
     // m.points[i].separation < 0 is penetration, .point is in world space

   The separating-axis test runs over both polygons' edge normals in A's
   own frame (so far from the origin it is as precise as near it).  The
   reference face is B's only when B's axis beats A's by 0.1 linear slop,
   so the choice does not flicker; the incident edge is clipped to the
   reference face; points up to the speculative distance (4 slop) apart
   are kept, so fast bodies are caught before they overlap; two polygons
   apart corner to corner get their true distance.  Each point's id names
   the features that made it and survives small motion.

   In a world, every body has a fat AABB (its box grown by
   GA2D_AABB_MARGIN) in one of two dynamic AABB trees, static or moving; a
   body that leaves its fat box is re-inserted and its new pairs found.
   Pairs need a dynamic body and a filter that allows them (ga2d_filter:
   category and mask bits, group index).  Each pair is a contact whose
   manifold is recomputed every step, unless the pair touches and has moved
   by under half a slop since its manifold was made: then that manifold is
   carried along with the bodies (counters.manifolds_carried), as the
   solver carries it between substeps (a round side's by its core, so a
   disc's point stays under its centre; two discs are collided anew);
   ga2d_world_get_contacts lists the
   touching ones and ga2d_world_contact_events which began and ended
   touching in the last step.  All tolerances scale with
   ga2d_world_def.length_units_per_meter.

   ==========================================================================
   THE CONTACT SOLVER
   ==========================================================================
   Each step finds pairs and manifolds, then builds a constraint per
   touching contact.  Restitution runs first, as a collision phase: a
   contact that will close this step while approaching faster than
   restitution_threshold (1 m/s) leaves at e times its impact speed, its
   points solved as one block, contact after contact until nothing
   collides (so an impact runs down a touching row: Newton's cradle).
   Then, per substep: velocities, warm start (last step's impulses, matched
   by feature id), one pass of sequential impulses with a soft bias
   (normals only), positions, and a relax pass without bias (normals, then
   friction and rolling resistance).  The passes run on groups of
   constraints that move no body in common, one per SIMD lane, each body's
   constraints in their canonical order: what one constraint at a time
   would compute, bit for bit, several at once.  The normal impulse at a point
   uses the paper's denominator in GA form,
       1/m_a + 1/m_b - (r_a ^ n)^2 / I_a - (r_b ^ n)^2 / I_b,
   (bivectors square to minus their coefficient squared), accumulated and
   kept >= 0; Coulomb friction keeps the tangent impulse within mu times it
   (mu mixes as sqrt(mu_a mu_b), e as max(e_a, e_b)).  Soft contacts are
   springs of contact_hertz (45 Hz, at most a quarter of the substep rate,
   twice that against static bodies) and damping ratio 10; overlap is
   pushed out at most contact_push_max_velocity (0.8 m/s) per contact:
   the cap bounds the speed of the push, never the load a contact
   carries, so a heavy body squashes a light one under it and does not
   pass through (it sinks about the mass ratio times what a body sinks
   into its equal: the spring is made for the light one's mass).

   Knobs: substeps; solver kind; contact_hertz; the switches for warm
   starting, friction, restitution and sleep; ga2d_accurate_world_def()
   (8 substeps, 90 Hz) for tighter stacks at about 1.7x the cost.

   Sleep: islands of touching dynamic bodies whose points all move under
   5 cm/s for 0.5 s sleep together: they leave the step (no integration, no
   broadphase refit, no narrowphase) and keep their state bit for bit.  A
   touch, a force, an impulse or a setter wakes the island.

   ==========================================================================
   ERRORS
   ==========================================================================
   Functions that can fail return a ga2d_result (GA2D_OK = 0) and leave
   their outputs untouched on failure; ga2d_result_string() names the code.
   Constructors that return a value (ga2d_polygon_box, ..._regular) return
   a polygon with count 0 for bad input, which every other function refuses.

   Bounds: coordinates within GA2D_MAX_COORDINATE; a step of at most
   GA2D_MAX_TIME_STEP whose substep h keeps |g| h^2 within a linear slop;
   |g| within GA2D_MAX_GRAVITY.  Beyond them: GA2D_ERR_TOO_LARGE.  A body
   driven past 400 m/s (or an eighth of a turn per substep) is capped, and
   counters.speed_caps counts it: a program that sees it nonzero after a
   step knows something in the scene is blowing up.

   Calls from inside the library's callbacks.  User code runs inside the
   library in five places: the force callback and the pre-solve callback
   (both during ga2d_world_step), the debug-draw callbacks (during
   ga2d_world_draw), the allocator's alloc and free (during any call that
   allocates, and ga2d_world_destroy), and nowhere else.  (The pre-solve
   callback is handed no world and a copy of the manifold: its answer is
   its only effect.  Through a world pointer of its own the rules below
   hold, except that forces are refused there too.)  From there, on the
   same world:
     - getters, counters, contact lists and ga2d_world_snapshot_size read
       the world as it is (mid-step, from the force callback or an
       allocation inside a step);
     - ga2d_body_apply_force, _apply_force_to_center and _apply_torque
       work from the force callback (they add to the field's force; on a
       sleeping body, one that is not zero wakes its island at the end of
       the step, for the next) and are refused elsewhere;
     - every other call that would change the world (creating or
       destroying bodies, setters, impulses, stepping, drawing, snapshot
       save and load, the world's set_ and enable_ calls) is refused with
       GA2D_ERR_LOCKED (ga2d_body_create returns the null id) and changes
       nothing;
     - ga2d_world_destroy is deferred: the library call under way finishes
       without calling back again and returns as usual, then the world is
       freed (do not use it after that call returns).  From a free hook of
       ga2d_world_destroy itself it does nothing; the world then reads as
       empty.
   Other worlds are unaffected: creating or stepping a second world from a
   callback is fine.

   The version history and the license are at the end of this file.
*/
#ifndef GA2D_PHYSICS_H
#define GA2D_PHYSICS_H

#include <stddef.h>
#include <stdint.h>

#define GA2D_VERSION_MAJOR 0
#define GA2D_VERSION_MINOR 9
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
    GA2D_ERR_TOO_LARGE,         /* beyond a documented bound: a coordinate
                                   (GA2D_MAX_COORDINATE), a step
                                   (GA2D_MAX_TIME_STEP, g h^2 <= slop), a
                                   gravity (GA2D_MAX_GRAVITY)              */
    GA2D_ERR_REPEATED_POINTS,   /* two points closer than the tolerance     */
    GA2D_ERR_COLLINEAR_POINTS,  /* a vertex on the line of its neighbours,
                                   or every point on one line               */
    GA2D_ERR_DEGENERATE,        /* zero or near-zero area                   */
    GA2D_ERR_CLOCKWISE,         /* vertices wound clockwise                 */
    GA2D_ERR_NOT_CONVEX,        /* not strictly convex (or self-crossing)   */
    GA2D_ERR_NOT_INVERTIBLE,    /* a multivector with no inverse            */
    GA2D_ERR_OUT_OF_MEMORY,
    GA2D_ERR_STALE_ID,          /* a destroyed, reused or forged body id  */
    GA2D_ERR_LOCKED,            /* called from a callback of this world's (force, draw, allocator) */
    GA2D_ERR_BAD_SNAPSHOT,      /* truncated, corrupted, another version or
                                   another build's snapshot                 */
    GA2D_ERR_BUFFER_TOO_SMALL,  /* the snapshot does not fit the buffer     */
    GA2D_ERR_MASS_OVERFLOW,     /* a body's mass, centre or inertia summed
                                   over its shapes would not be finite      */
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
   normal of edge i (from vertex i to vertex i+1).  radius > 0 rounds it:
   the shape is every point within radius of the polygon (its corners are
   arcs, its edges pushed out by radius); 0 is sharp. */
typedef struct ga2d_polygon {
    int count;
    ga2d_vec vertices[GA2D_MAX_POLYGON_VERTICES];
    ga2d_vec normals[GA2D_MAX_POLYGON_VERTICES];
    ga2d_real radius;
} ga2d_polygon;

/* The round shapes, in their body's frame: a disc; a capsule, every point
   within radius of the segment center1-center2; a segment (no area: a
   wall or a piece of terrain, on static and kinematic bodies). */
typedef struct ga2d_circle { ga2d_vec center; ga2d_real radius; } ga2d_circle;
typedef struct ga2d_capsule { ga2d_vec center1, center2; ga2d_real radius; } ga2d_capsule;
typedef struct ga2d_segment { ga2d_vec point1, point2; } ga2d_segment;
/* A segment of a chain: its neighbours' far ends (ghost1 before point1,
   ghost2 after point2) let a body slide across the joins without catching.
   One-sided: it pushes only toward its left, the side its normal
   (point2 - point1) e12 points to.  A ghost gives only a direction: at an
   open end of a chain it is made up, at a right angle behind the end and
   twice the end segment's length from it, so it may lie up to
   5 GA2D_MAX_COORDINATE out (the end's M plus twice a segment's 2 M). */
typedef struct ga2d_chain_segment { ga2d_vec ghost1; ga2d_segment segment; ga2d_vec ghost2; } ga2d_chain_segment;

typedef enum ga2d_shape_type {
    GA2D_SHAPE_CIRCLE,
    GA2D_SHAPE_CAPSULE,
    GA2D_SHAPE_POLYGON,
    GA2D_SHAPE_SEGMENT,
    GA2D_SHAPE_CHAIN_SEGMENT, /* a segment of a chain, with its neighbours' ghost vertices */
    GA2D_SHAPE_TYPE_COUNT
} ga2d_shape_type;

/* One shape's geometry, for the world-free collider: `type` names the
   member of `as` in use (circle, capsule, polygon or segment). */
typedef struct ga2d_geometry {
    ga2d_shape_type type;
    union {
        ga2d_circle circle;
        ga2d_capsule capsule;
        ga2d_polygon polygon;
        ga2d_segment segment;
        ga2d_chain_segment chain_segment;
    } as;
} ga2d_geometry;

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
   TOO_LARGE, REPEATED_POINTS, DEGENERATE (L below GA2D_MIN_EXTENT, or so
   small that 1e-5 L^2 is not a normal number: float L < 2.4e-17, double
   L < 1e-15),
   COLLINEAR_POINTS (all on one line), DEGENERATE, CLOCKWISE,
   COLLINEAR_POINTS (one vertex), NOT_CONVEX. */
GA2D_API ga2d_result ga2d_polygon_make(const ga2d_vec *pts, int n, ga2d_polygon *out);
/* The convex hull of any n >= 3 points: near-duplicates welded and points
   on an edge dropped (tolerance 4x that of ga2d_polygon_make), CCW from the
   lowest-x vertex.  Fails with TOO_FEW_POINTS (fewer than 3 distinct
   points), COLLINEAR_POINTS, TOO_MANY_POINTS (the hull has more than
   GA2D_MAX_POLYGON_VERTICES), NOT_FINITE, TOO_LARGE or DEGENERATE (also
   for a cloud too small for ga2d_polygon_make, whatever its shape).
   Needs no memory beyond the stack: Andrew's monotone chains, wrapped
   without sorting, O(n h). */
GA2D_API ga2d_result ga2d_polygon_hull(const ga2d_vec *pts, int n, ga2d_polygon *out);
/* Axis-aligned box centred on the origin; count 0 if a half-extent is not
   finite and positive (ga2d_polygon_rounded_box_checked says why). */
GA2D_API ga2d_polygon ga2d_polygon_box(ga2d_real half_width, ga2d_real half_height);
/* The box of half-extents hw x hh rounded by r: its core is the box
   shrunk by r, so the shape's outline still spans 2 hw x 2 hh; r = 0 is
   ga2d_polygon_box.  Count 0 on failure; the checked form returns
   INVALID_ARGUMENT (r < 0, a half-extent <= 0 or <= r: make a capsule or
   a circle), NOT_FINITE, TOO_LARGE, or ga2d_polygon_make's answer for a
   core too thin to be a polygon. */
GA2D_API ga2d_polygon ga2d_polygon_rounded_box(ga2d_real hw, ga2d_real hh, ga2d_real r);
GA2D_API ga2d_result ga2d_polygon_rounded_box_checked(ga2d_real hw, ga2d_real hh, ga2d_real r, ga2d_polygon *out);
/* Regular n-gon of circumradius r centred on the origin, vertex 0 on +x;
   count 0 on failure.  The checked form says why: TOO_FEW_POINTS (n < 3),
   TOO_MANY_POINTS (n > GA2D_MAX_POLYGON_VERTICES: raise it for the build,
   or use a circle), NOT_FINITE, INVALID_ARGUMENT (r <= 0), and
   ga2d_polygon_make's answers for an r too small or too large. */
GA2D_API ga2d_polygon ga2d_polygon_regular(int n, ga2d_real radius);
GA2D_API ga2d_result ga2d_polygon_regular_checked(int n, ga2d_real radius, ga2d_polygon *out);
/* AABB of the polygon placed by x, its radius included. */
GA2D_API ga2d_aabb ga2d_polygon_aabb(const ga2d_polygon *p, ga2d_transform x);
/* Exact mass properties at the given density (mass per unit area), the
   radius included: polygon, edge strips and corner sectors.  All zero
   when p is NULL or has a bad count, or density or the radius is negative
   or not finite; use ga2d_polygon_mass_checked to be told why. */
GA2D_API ga2d_mass ga2d_polygon_mass(const ga2d_polygon *p, ga2d_real density);
GA2D_API ga2d_result ga2d_polygon_mass_checked(const ga2d_polygon *p, ga2d_real density,
                                               ga2d_mass *out);
/* Exact mass properties of a disc (I = m r^2 / 2) and of a capsule (a
   rectangle and two half discs; a capsule of zero length is the disc,
   radius 0 has no area).  All zero on bad input; the checked forms say
   why: INVALID_ARGUMENT (NULL, a negative radius or density), NOT_FINITE,
   TOO_LARGE. */
GA2D_API ga2d_mass ga2d_circle_mass(const ga2d_circle *c, ga2d_real density);
GA2D_API ga2d_result ga2d_circle_mass_checked(const ga2d_circle *c, ga2d_real density, ga2d_mass *out);
GA2D_API ga2d_mass ga2d_capsule_mass(const ga2d_capsule *c, ga2d_real density);
GA2D_API ga2d_result ga2d_capsule_mass_checked(const ga2d_capsule *c, ga2d_real density, ga2d_mass *out);

/* The largest |coordinate| a polygon vertex may have.  Float: inertia
   grows as the 4th power of size, and every wedge-sum term must stay
   finite with room for densities up to ~1e6: (3.4e38 / 1.2e4 / 1e6)^(1/4)
   ~ 1.2e8.  Double could go to ~1e75 by that measure, but doubles past
   1e15 are 0.125 or more apart, coarser than any contact tolerance at a
   sane length unit: such a polygon is a mistake, and is refused (as 1e30
   is in float).  Define it before including the header to change it. */
#ifndef GA2D_MAX_COORDINATE
#ifdef GA2D_DOUBLE
#define GA2D_MAX_COORDINATE 1e15
#else
#define GA2D_MAX_COORDINATE 1e8f
#endif
#endif

/* The smallest extent (larger side of the bounding box) a polygon may
   have.  Float refuses what its arithmetic cannot measure (1e-5 L^2 below
   the smallest normal number: L < 2.4e-17); double could measure down to
   3e-152, but a polygon under 1e-15 (a femtometre at one unit per metre)
   is a mistake too, refused with DEGENERATE.  Overridable like the above. */
#ifndef GA2D_MIN_EXTENT
#ifdef GA2D_DOUBLE
#define GA2D_MIN_EXTENT 1e-15
#else
#define GA2D_MIN_EXTENT 0.0f
#endif
#endif

/* ------------------------------------------------------- world and bodies */
typedef struct ga2d_world ga2d_world;

/* A body handle: slot index + 1 and the slot's generation.  The zero value
   is the null id.  A destroyed body's id stays invalid after its slot is
   reused (the generation moves on), and a forged id is refused. */
typedef struct ga2d_body_id { uint32_t index1; uint32_t generation; } ga2d_body_id;
GA2D_API ga2d_body_id ga2d_body_id_null(void);
GA2D_API int ga2d_body_id_is_null(ga2d_body_id id);
/* A shape handle, as a body's (see "shapes"). */
typedef struct ga2d_shape_id { uint32_t index1; uint32_t generation; } ga2d_shape_id;
GA2D_API int ga2d_body_id_equal(ga2d_body_id a, ga2d_body_id b);

/* Memory for a world.  NULL functions mean malloc/free.  free gets the size
   that was asked for, so an arena or a counting allocator needs no header. */
typedef struct ga2d_allocator {
    void *(*alloc)(size_t size, void *ctx);
    void (*free)(void *ptr, size_t size, void *ctx);
    void *ctx;
} ga2d_allocator;

typedef enum ga2d_integrator {
    GA2D_INTEGRATOR_SYMPLECTIC_EULER = 0, /* v += h a(x); x += h v: 1st order,
                                             symplectic, 1 evaluation */
    GA2D_INTEGRATOR_VERLET,               /* velocity Verlet: 2nd order,
                                             symplectic, exact for constant a;
                                             forces must depend on position
                                             only; 1 evaluation (reused) */
    GA2D_INTEGRATOR_RK4,                  /* classic Runge-Kutta: 4th order,
                                             not symplectic, 4 evaluations */
    GA2D_INTEGRATOR_COUNT
} ga2d_integrator;

typedef enum ga2d_rotation_update {
    GA2D_ROTATION_EXACT = 0, /* q <- q exp(w h e12): exact for constant w */
    GA2D_ROTATION_LINEAR,    /* q <- normalize(q (1 + w h e12)): a sqrt
                                instead of a series; lags atan(wh) vs wh */
    GA2D_ROTATION_COUNT
} ga2d_rotation_update;

/* How contacts are solved.  Each substep integrates velocities,
   solves the contacts, integrates positions; the kinds differ in how they
   remove overlap:
     SOFT_STEP      soft contacts (a spring-damper of contact_hertz and
                    contact_damping_ratio, push-out capped at
                    contact_push_max_velocity), then a relax pass without
                    bias: the overlap never adds energy (the default).
                    Friction acts in the relax pass and the warm start.
     PGS_BAUMGARTE  velocity_iterations rigid passes with a position error
                    feedback (Baumgarte, 0.2 / h of the overlap past slop).
     PGS_NGS        velocity_iterations rigid passes without feedback, then
                    position_iterations passes that move the bodies apart
                    directly (non-linear Gauss-Seidel). */
typedef enum ga2d_solver {
    GA2D_SOLVER_SOFT_STEP = 0,
    GA2D_SOLVER_PGS_BAUMGARTE,
    GA2D_SOLVER_PGS_NGS,
    GA2D_SOLVER_COUNT
} ga2d_solver;

typedef enum ga2d_body_type {
    GA2D_BODY_STATIC = 0, /* never moves; costs nothing per step */
    GA2D_BODY_KINEMATIC,  /* moves with its velocity; no forces */
    GA2D_BODY_DYNAMIC,    /* moves under forces, torques and impulses */
    GA2D_BODY_TYPE_COUNT
} ga2d_body_type;

/* A force field, evaluated by the step at every state its integrator needs
   (once per substep for symplectic Euler and Verlet, four times for RK4).
   Inside it, the getters (ga2d_body_center, _velocity, ...) return the
   state being evaluated and ga2d_world_time the time of that state;
   ga2d_body_apply_force / _apply_torque add to the field's force.  A
   sleeping body is not evaluated: a push on it that is not zero wakes its
   island at the end of the step, and the island joins the next step (a
   field that holds resting bodies, a planet's pull, thus wakes them each
   time they fall asleep: skip the bodies that sleep, ga2d_body_is_awake,
   where that is not wanted).  Any
   other change to the world is refused with GA2D_ERR_LOCKED, and
   ga2d_world_destroy waits for the step to end (see ERRORS above). */
typedef void ga2d_force_fn(ga2d_world *world, void *context);

/* Bounds on a step, in seconds and metres (gravity scales with
   length_units_per_meter).  A step longer than GA2D_MAX_TIME_STEP (the
   sleep timer's span: a longer one is a pause, not a step) is refused with
   GA2D_ERR_TOO_LARGE, and so is one whose substep h lets gravity move a
   body from rest by more than a linear slop (|g| h^2 > GA2D_LINEAR_SLOP):
   the contact under a resting body could no longer hold it within the
   slop, and a stack sinks.  At g = 10 that is h <= 22 ms (dt <= 89 ms
   with 4 substeps); raise substeps for longer steps.  GA2D_MAX_GRAVITY is
   the most that GA2D_MAX_SUBSTEPS of the longest step keep within that.
   Substeps and solver iterations are each at most GA2D_MAX_SUBSTEPS. */
#define GA2D_MAX_TIME_STEP 0.5
#define GA2D_MAX_SUBSTEPS 1024
#define GA2D_MAX_GRAVITY \
    (GA2D_LINEAR_SLOP * (GA2D_MAX_SUBSTEPS / GA2D_MAX_TIME_STEP) * (GA2D_MAX_SUBSTEPS / GA2D_MAX_TIME_STEP))

/* Defaults, in metres, kilograms and seconds (a world scales lengths by
   its length_units_per_meter).  ga2d_default_world_def() and
   ga2d_default_body_def() return them, and a def's zeros resolve to them
   (see "Defs" below).  Define one before including the header to change
   it for a whole build. */
#ifndef GA2D_DEFAULT_GRAVITY
#define GA2D_DEFAULT_GRAVITY (-10.0)          /* m/s^2, along y */
#endif
#ifndef GA2D_DEFAULT_SUBSTEPS
#define GA2D_DEFAULT_SUBSTEPS 4               /* substeps per step */
#endif
#ifndef GA2D_DEFAULT_VELOCITY_ITERATIONS
#define GA2D_DEFAULT_VELOCITY_ITERATIONS 8    /* PGS passes per substep */
#endif
#ifndef GA2D_DEFAULT_POSITION_ITERATIONS
#define GA2D_DEFAULT_POSITION_ITERATIONS 3    /* NGS passes per substep */
#endif
#ifndef GA2D_DEFAULT_CONTACT_HERTZ
#define GA2D_DEFAULT_CONTACT_HERTZ 45.0       /* Hz: soft contact stiffness */
#endif
#ifndef GA2D_DEFAULT_CONTACT_DAMPING_RATIO
#define GA2D_DEFAULT_CONTACT_DAMPING_RATIO 10.0 /* of the soft contact spring */
#endif
#ifndef GA2D_DEFAULT_CONTACT_PUSH_MAX_VELOCITY
#define GA2D_DEFAULT_CONTACT_PUSH_MAX_VELOCITY 0.8 /* m/s: push-out speed per contact */
#endif
#ifndef GA2D_DEFAULT_RESTITUTION_THRESHOLD
#define GA2D_DEFAULT_RESTITUTION_THRESHOLD 1.0 /* m/s: slower impacts do not bounce */
#endif
#ifndef GA2D_DEFAULT_HIT_EVENT_THRESHOLD
#define GA2D_DEFAULT_HIT_EVENT_THRESHOLD 1.0   /* m/s: slower approaches are no hit */
#endif
#ifndef GA2D_DEFAULT_DENSITY
#define GA2D_DEFAULT_DENSITY 1.0              /* kg/m^2 */
#endif
#ifndef GA2D_DEFAULT_FRICTION
#define GA2D_DEFAULT_FRICTION 0.6             /* Coulomb coefficient */
#endif
/* Caps on motion, as Box2D's: a body faster than this, or turning more
   per substep, is tunnelling anyway; the step caps it and counts it in
   counters.speed_caps. */
#ifndef GA2D_MAX_LINEAR_SPEED
#define GA2D_MAX_LINEAR_SPEED 400.0           /* m/s */
#endif
#ifndef GA2D_MAX_ROTATION
#define GA2D_MAX_ROTATION (0.25 * 3.14159265358979323846) /* rad per substep */
#endif

/* Defs.  Get one from ga2d_default_world_def() (or _body_def()) and set
   what you need: every field is then taken as you leave it.  A def
   zero-initialised by hand (= {0}, memset) is the defaults: each field it
   leaves at zero takes its default value, switches included, so it steps
   bit for bit as the default def does.  The default functions stamp
   internal_cookie, which is how a def tells the two apart; to set a field
   to zero where its default is not zero (sleep off, weightless,
   frictionless), start from the default function.  Fields marked "0
   means" resolve their zero in every def. */
#define GA2D_DEF_COOKIE 0x67613264 /* "ga2d" */

/* Called in each step, before the solver, for every touching contact one
   of whose shapes has enable_pre_solve_events, with the two shapes (A
   before B; the normal points from A to B) and the manifold: return 0 and
   the contact does not push this step (a one-way platform: 0 when the
   body comes from below, normal.y of the platform's side < 0).  The world
   is locked: read it, change nothing.  The manifold is a copy, the
   callback's own while it runs: what it writes there reaches nothing. */
struct ga2d_manifold;
typedef int ga2d_pre_solve_fn(ga2d_shape_id shape_a, ga2d_shape_id shape_b, const struct ga2d_manifold *m, void *context);

/* Threads through the user's task system (Box2D v3's shape): the world
   never starts a thread.  enqueue_task splits items [0, item_count) into
   ranges of at least min_range items, calls task(start, end, worker,
   task_context) for each on any of its worker_count workers (worker in
   [0, worker_count)), and returns a handle for finish_task, which waits
   for all of them; or it runs them itself and returns NULL (finish_task
   is then not called).  The step hands over ranges of the stages whose
   items write only their own data: the narrowphase, the bodies' marks,
   kicks and drifts, preparing the contacts and filling the solver's
   lanes; and the solver passes, whose constraints are coloured so that
   no two of a colour move one body.  Under gcc and clang a substep's
   passes go as one job of worker_count items, each a member of a team
   that shares out every colour of every pass among the members running,
   with atomics of its own: a member waits only for blocks another has
   taken, never for a member not yet started, so a task system may run
   the items one after the other, or fewer at once than worker_count
   (elsewhere each colour of a pass is a job).  So a step makes a few
   dozen jobs, microseconds apart: a task system whose workers sleep
   between jobs loses to one that spins a moment first
   (examples/task_pool.h).  The joints, ordering the contacts and
   colouring them still run on the calling thread.  Results are the same
   bits for any worker count and any split.  The world is locked while a
   task runs: a task system must not call it. */
typedef void ga2d_task_fn(int start_index, int end_index, int worker_index, void *task_context);
typedef void *ga2d_enqueue_task_fn(ga2d_task_fn *task, int item_count, int min_range, void *task_context, void *user_context);
typedef void ga2d_finish_task_fn(void *user_task, void *user_context);
#define GA2D_MAX_WORKERS 256

typedef struct ga2d_world_def {
    ga2d_vec gravity;                     /* m/s^2; default (0, -10), |g| <= GA2D_MAX_GRAVITY */
    int substeps;                         /* per step; 0 means 4 */
    ga2d_integrator integrator;           /* default symplectic Euler */
    ga2d_rotation_update rotation_update; /* default exact */
    ga2d_real length_units_per_meter;     /* 0 means 1 */
    ga2d_allocator allocator;             /* zero means malloc/free */
    ga2d_force_fn *force_callback;        /* NULL: no force field */
    void *force_context;
    ga2d_solver solver;                   /* default soft step */
    int velocity_iterations;              /* PGS kinds, per substep; 0 means 8 */
    int position_iterations;              /* PGS_NGS, per substep; 0 means 3 */
    ga2d_real contact_hertz;              /* soft contact stiffness, at most a quarter
                                             of the substep rate; 0 means 45 */
    ga2d_real contact_damping_ratio;      /* 0 means 10 */
    ga2d_real contact_push_max_velocity;  /* m/s per contact; 0 means 0.8 (pushes
                                             add up along a stack: at 0.8 ten
                                             boxes overlapped 25% part in 0.8 s,
                                             none faster than 5.7 m/s; at 3,
                                             Box2D's, the top one flies at 17) */
    ga2d_real restitution_threshold;      /* m/s of approach; 0 means 1 */
    int enable_sleep;                     /* islands at rest sleep (default 1) */
    int enable_warm_starting;             /* reuse last step's impulses (default 1) */
    int enable_friction;                  /* default 1 */
    int enable_restitution;               /* default 1 */
    ga2d_pre_solve_fn *pre_solve;         /* NULL: none (see ga2d_pre_solve_fn) */
    void *pre_solve_context;
    ga2d_real hit_event_threshold;        /* m/s of approach for a hit event; 0 means 1 */
    int enable_continuous;                /* sweep fast bodies against static shapes
                                             (default 1; see ga2d_body_def.is_bullet) */
    int worker_count;                     /* 0 or 1: one thread; at most GA2D_MAX_WORKERS */
    ga2d_enqueue_task_fn *enqueue_task;   /* NULL: the step runs every stage itself */
    ga2d_finish_task_fn *finish_task;     /* set with enqueue_task, or neither */
    void *user_task_context;
    int internal_cookie;                  /* set by the default functions; leave it */
} ga2d_world_def;

/* Collision filtering, per body.  Two bodies in the same nonzero group
   always collide (positive group) or never do (negative group); otherwise
   they collide when each one's category is in the other's mask. */
typedef struct ga2d_filter {
    uint32_t category_bits; /* default 1 */
    uint32_t mask_bits;     /* default all */
    int32_t group_index;    /* default 0 */
} ga2d_filter;
typedef struct ga2d_body_def {
    ga2d_body_type type;        /* default static */
    ga2d_vec position;          /* the body origin, in world coordinates */
    ga2d_rotor rotor;           /* orientation; zero means identity */
    ga2d_vec velocity;          /* of the centre of mass, m/s */
    ga2d_real angular_velocity; /* w of Omega = w e12, rad/s */
    ga2d_polygon polygon;       /* in the body frame: its first shape, made with
                                   the def's density, friction, restitution and
                                   filter; count 0 (the default): no shape */
    ga2d_real density;          /* kg/m^2; default 1 */
    ga2d_real friction;         /* default 0.6 */
    ga2d_real restitution;      /* default 0 */
    ga2d_real linear_damping;   /* 1/s; default 0 */
    ga2d_real angular_damping;  /* 1/s; default 0 */
    ga2d_real gravity_scale;    /* default 1 */
    int fixed_rotation;         /* never rotates (infinite inertia) */
    int is_awake;               /* default 1 */
    void *user_data;
    ga2d_filter filter;         /* default: category 1, collides with all */
    int is_bullet;              /* a dynamic body swept against moving bodies too
                                   (continuous collision; default 0) */
    int internal_cookie;        /* set by ga2d_default_body_def(); leave it */
} ga2d_body_def;

/* What the last step did: for checking that a scene pays only for what it
   uses, without timing anything. */
typedef struct ga2d_world_counters {
    int body_count;         /* live bodies of every type */
    int moving_body_count;  /* kinematic + dynamic: the bodies a step visits */
    int integrated_bodies;  /* body updates in the last step, all substeps */
    int force_evaluations;  /* force callback calls in the last step */
    int rotation_updates;   /* rotor updates in the last step */
    long long step_count;   /* steps taken */
    int pair_count;         /* broadphase pairs (contacts, touching or not) */
    int touching_count;     /* contacts with manifold points */
    int constraint_count;   /* contacts solved in the last step */
    int awake_body_count;   /* dynamic bodies awake */
    int island_count;       /* islands found in the last step (sleep on) */
    int speed_caps;         /* times the last step capped a body's speed
                               (GA2D_MAX_LINEAR_SPEED) or turn (GA2D_MAX_ROTATION per
                               substep), per body and substep: a body
                               driven that fast is blowing up, and this is
                               how a program notices (the step still
                               returns GA2D_OK; NaN and Inf are reported
                               by the step itself) */
    int manifolds_carried;  /* touching manifolds the last step carried
                               along rather than computed anew (pairs that
                               moved by under half a slop) */
    int shape_count;        /* live shapes */
    int sensor_tests;       /* overlap tests the sensors made in the last
                               step (0 in a world without sensors) */
    int round_contacts;     /* contacts solved in the last step with a
                               round shape (the solver's round-anchor work) */
    int joint_count;        /* live joints */
    int joints_solved;      /* joints the last step solved (0 in a world
                               without joints, or with all of them asleep) */
    int continuous_bodies;  /* fast bodies the last step swept (continuous
                               collision; 0 in a scene where nothing is fast) */
    int continuous_hits;    /* of those, the ones it stopped at an impact */
    int query_nodes;        /* broadphase tree nodes the last world query
                               visited (ga2d_world_cast_ray, overlap_*) */
    int query_shapes;       /* shapes it tested exactly (their boxes met
                               the query's) */
    int hinges_in_lanes;    /* of joints_solved, the bare revolute joints (no
                               spring, motor or limit) the last step solved
                               several at a time in the solver's lanes */
    int colouring_kept;     /* 1 when the last step kept the step before's
                               colouring of its contacts and joints (the
                               same bodies touching and joined, moved the
                               same way), 0 when it coloured them anew */
    int boxes_kept;         /* moving bodies whose tree boxes the last step
                               kept on their motion alone, without finding
                               their shapes' boxes (the others' were found) */
    int trees_rebuilt;      /* broadphase trees the last step built again from
                               their leaves, because most of their shapes had
                               left their boxes (0 in a scene at rest) */
} ga2d_world_counters;

GA2D_API ga2d_world_def ga2d_default_world_def(void);
/* Why a def would be refused: NOT_FINITE gravity, INVALID_ARGUMENT for a
   bad enum, substeps outside [0, GA2D_MAX_SUBSTEPS], a negative length
   unit or half an allocator. */
GA2D_API ga2d_result ga2d_world_def_validate(const ga2d_world_def *def);
GA2D_API ga2d_world *ga2d_world_create(const ga2d_world_def *def); /* NULL on failure; def NULL = defaults */
GA2D_API void ga2d_world_destroy(ga2d_world *w);
/* Advances by dt seconds in substeps.  A dt that is not finite and > 0 is
   refused (GA2D_ERR_INVALID_ARGUMENT) and nothing changes. */
GA2D_API ga2d_result ga2d_world_step(ga2d_world *w, ga2d_real dt);
/* After a step that returned GA2D_ERR_NOT_FINITE: a body whose state the
   step found not finite (a user force, impulse or field drove it there);
   of several, the one of lowest id index, whatever order the step met
   them in (a world loaded from a snapshot names the same one).  The step put it back where the step began, at rest, its forces
   cleared, before its neighbours could see it (they stay finite); the rest
   of the step moved it as any body.  The null id when the last step
   contained nothing. */
GA2D_API ga2d_body_id ga2d_world_error_body(const ga2d_world *w);
GA2D_API double ga2d_world_time(const ga2d_world *w);
GA2D_API ga2d_world_counters ga2d_world_get_counters(const ga2d_world *w);
GA2D_API ga2d_vec ga2d_world_gravity(const ga2d_world *w);
GA2D_API ga2d_result ga2d_world_set_gravity(ga2d_world *w, ga2d_vec g);
GA2D_API ga2d_result ga2d_world_set_substeps(ga2d_world *w, int substeps);
/* May allocate (RK4 keeps per-body scratch): OUT_OF_MEMORY leaves it as it was. */
GA2D_API ga2d_result ga2d_world_set_integrator(ga2d_world *w, ga2d_integrator integrator);
GA2D_API ga2d_result ga2d_world_set_rotation_update(ga2d_world *w, ga2d_rotation_update mode);
GA2D_API ga2d_result ga2d_world_set_force_callback(ga2d_world *w, ga2d_force_fn *fn, void *context);
GA2D_API ga2d_result ga2d_world_set_solver(ga2d_world *w, ga2d_solver solver);
/* Switches: sleep (turning it off wakes every body), warm starting,
   friction and restitution.  A switched-off pass costs nothing. */
GA2D_API ga2d_result ga2d_world_enable_sleep(ga2d_world *w, int on);
GA2D_API ga2d_result ga2d_world_enable_warm_starting(ga2d_world *w, int on);
GA2D_API ga2d_result ga2d_world_enable_friction(ga2d_world *w, int on);
GA2D_API ga2d_result ga2d_world_enable_restitution(ga2d_world *w, int on);
/* Continuous collision: a dynamic body that moves more than half its
   thinnest shape's thickness in a step is swept from where the step began
   to where it ended and stopped at its first impact with a static shape
   (within GA2D_LINEAR_SLOP of touching; a bullet with moving shapes too),
   its velocity kept: it loses the rest of that step's motion, and the
   next step's contacts take it from there.  A chain segment stops only a
   body that crosses it from its front.  Bodies that are not fast cost a
   motion test (counters.continuous_bodies counts the swept ones). */
GA2D_API ga2d_result ga2d_world_enable_continuous(ga2d_world *w, int on);
/* The documented accurate setting: 8 substeps and 90 Hz contacts (twice
   the substeps, and contacts twice as stiff, which a doubled substep rate
   allows).  A 10-box stack sinks 4 mm instead of 15, at about 1.7 times
   the cost per step. */
GA2D_API ga2d_world_def ga2d_accurate_world_def(void);

/* Gives memory back.  A world keeps the largest arrays it has needed (the
   contact pool at its peak pair count, the pair set, the solver's scratch)
   so that steps allocate nothing once a scene has settled.  After a scene
   shrinks for good (a level cleared, most bodies destroyed), compact:
   the live contacts move to a pool of their own size (in creation order:
   the steps that follow give the same bits as without compacting), the
   pair set is rebuilt to fit, and the per-step scratch is freed (the next
   step allocates it again, at its new size).  OUT_OF_MEMORY or LOCKED
   leave the world as it was.  Contact event arrays stay valid. */
GA2D_API ga2d_result ga2d_world_compact(ga2d_world *w);

/* Snapshots, for rollback and replays: the whole world as a plain byte
   buffer (versioned, with a checksum) that loads back into any world of
   the same build (same ga2d_real, GA2D_MAX_POLYGON_VERTICES and ABI).
   Load, then step, gives the same bits as the original steps: contacts and
   their warm-start impulses are in it, and the solver's order does not
   depend on where things sit in memory.  The loading world keeps its own
   allocator and force callback; user_data pointers (bodies', shapes' and
   joints') are restored as saved (they mean something only in the process
   that saved them).
   save: BUFFER_TOO_SMALL if cap < ga2d_world_snapshot_size(w) (buf
   untouched), OUT_OF_MEMORY.  load: BAD_SNAPSHOT for a truncated,
   corrupted or wrong-version buffer, OUT_OF_MEMORY, LOCKED; on any error
   the world is exactly as it was.  Neither may be called while the world
   steps. */
GA2D_API size_t ga2d_world_snapshot_size(const ga2d_world *w);
GA2D_API ga2d_result ga2d_world_snapshot_save(const ga2d_world *w, void *buf, size_t cap);
GA2D_API ga2d_result ga2d_world_snapshot_load(ga2d_world *w, const void *buf, size_t size);

GA2D_API ga2d_body_def ga2d_default_body_def(void);
/* Why a def would be refused: NOT_FINITE anywhere, TOO_LARGE for a
   position beyond GA2D_MAX_COORDINATE, INVALID_ARGUMENT for a bad type, a density <= 0 (dynamic bodies), a negative friction,
   restitution or damping, a rotor too small to normalize; the polygon's
   own error from ga2d_polygon_make; DEGENERATE for a mass or inertia
   whose inverse overflows. */
GA2D_API ga2d_result ga2d_body_def_validate(const ga2d_body_def *def);
/* The null id on failure (ga2d_body_def_validate says why; or out of
   memory; or the world is locked). */
GA2D_API ga2d_body_id ga2d_body_create(ga2d_world *w, const ga2d_body_def *def);
GA2D_API ga2d_result ga2d_body_destroy(ga2d_world *w, ga2d_body_id id);
GA2D_API int ga2d_body_is_valid(const ga2d_world *w, ga2d_body_id id);
/* A sleeping body costs nothing per step and keeps its state bit for bit.
   Touches, forces, impulses and setters wake it with its whole island.  A
   force or torque that is not zero from the force callback on a sleeping
   body wakes its island at the end of that step (the step has begun
   without it): the island joins the next step, where the callback's
   force acts on it. */
GA2D_API int ga2d_body_is_awake(const ga2d_world *w, ga2d_body_id id);
GA2D_API ga2d_result ga2d_body_set_awake(ga2d_world *w, ga2d_body_id id, int awake);

/* Getters: for an invalid id they return zero (identity for rotors).
   Names: a property reads as its noun (ga2d_body_position,
   ga2d_world_gravity); get_ marks a call that fills the caller's array
   (ga2d_world_get_contacts) or whose noun is a type's name already
   (ga2d_body_get_type, ga2d_world_get_counters). */
GA2D_API ga2d_body_type ga2d_body_get_type(const ga2d_world *w, ga2d_body_id id);
GA2D_API ga2d_vec ga2d_body_position(const ga2d_world *w, ga2d_body_id id); /* origin */
GA2D_API ga2d_rotor ga2d_body_rotor(const ga2d_world *w, ga2d_body_id id);
GA2D_API ga2d_real ga2d_body_angle(const ga2d_world *w, ga2d_body_id id);
GA2D_API ga2d_transform ga2d_body_transform(const ga2d_world *w, ga2d_body_id id);
GA2D_API ga2d_vec ga2d_body_center(const ga2d_world *w, ga2d_body_id id); /* centre of mass, world */
GA2D_API ga2d_vec ga2d_body_velocity(const ga2d_world *w, ga2d_body_id id); /* of the centre */
GA2D_API ga2d_real ga2d_body_angular_velocity(const ga2d_world *w, ga2d_body_id id);
/* velocity of the body point at world point p: v + (p - c) Omega */
GA2D_API ga2d_vec ga2d_body_velocity_at(const ga2d_world *w, ga2d_body_id id, ga2d_vec p);
GA2D_API ga2d_mass ga2d_body_mass_data(const ga2d_world *w, ga2d_body_id id); /* center in body frame */
GA2D_API ga2d_real ga2d_body_kinetic_energy(const ga2d_world *w, ga2d_body_id id);
/* The body's first polygon shape, or NULL.  Points into the world's
   shapes: valid until the next call that creates a shape on any body
   (ga2d_shape_create_*, ga2d_chain_create, ga2d_body_create with a
   polygon) or loads a snapshot (each may move the shapes), or until that
   shape, its body or the world is destroyed.  Copy the polygon to keep
   it. */
GA2D_API const ga2d_polygon *ga2d_body_polygon(const ga2d_world *w, ga2d_body_id id);
GA2D_API void *ga2d_body_user_data(const ga2d_world *w, ga2d_body_id id);

/* Setters validate (STALE_ID, NOT_FINITE, INVALID_ARGUMENT, LOCKED) and
   change nothing when they refuse.  A rotor must be nonzero and large
   enough to normalize; a static body takes no velocity; a dynamic body
   that cannot turn (fixed rotation, or inertia 0) takes no angular
   velocity but 0.  Forces, torques and impulses whose sums would overflow
   are refused with NOT_FINITE, as are a transform or mass data that would
   put the centre of mass beyond the largest finite number; a position or
   a centre of mass (in the body frame) beyond GA2D_MAX_COORDINATE is
   TOO_LARGE. */
GA2D_API ga2d_result ga2d_body_set_transform(ga2d_world *w, ga2d_body_id id, ga2d_vec position, ga2d_rotor q);
GA2D_API ga2d_result ga2d_body_set_velocity(ga2d_world *w, ga2d_body_id id, ga2d_vec v);
GA2D_API ga2d_result ga2d_body_set_angular_velocity(ga2d_world *w, ga2d_body_id id, ga2d_real omega);
/* Replace the mass properties from the polygon (mass > 0, inertia > 0 or
   0 for no rotation, centre in the body frame).  The origin stays put;
   the centre's velocity follows the rigid motion. */
GA2D_API ga2d_result ga2d_body_set_mass_data(ga2d_world *w, ga2d_body_id id, ga2d_mass m);
GA2D_API ga2d_result ga2d_body_set_gravity_scale(ga2d_world *w, ga2d_body_id id, ga2d_real scale);
GA2D_API ga2d_result ga2d_body_set_damping(ga2d_world *w, ga2d_body_id id, ga2d_real linear, ga2d_real angular);
GA2D_API ga2d_result ga2d_body_set_user_data(ga2d_world *w, ga2d_body_id id, void *user_data);
/* A bullet is swept against moving bodies too (ga2d_world_enable_continuous). */
GA2D_API ga2d_result ga2d_body_set_bullet(ga2d_world *w, ga2d_body_id id, int bullet);
GA2D_API int ga2d_body_is_bullet(const ga2d_world *w, ga2d_body_id id);

/* Forces and torques act during the next step, then are cleared.  Impulses
   act at once: dv = P/m, dOmega = I^-1 (r ^ P).  On static and kinematic
   bodies they do nothing (and return GA2D_OK). */
GA2D_API ga2d_result ga2d_body_apply_force(ga2d_world *w, ga2d_body_id id, ga2d_vec force, ga2d_vec world_point);
GA2D_API ga2d_result ga2d_body_apply_force_to_center(ga2d_world *w, ga2d_body_id id, ga2d_vec force);
GA2D_API ga2d_result ga2d_body_apply_torque(ga2d_world *w, ga2d_body_id id, ga2d_real torque_e12);
GA2D_API ga2d_result ga2d_body_apply_impulse(ga2d_world *w, ga2d_body_id id, ga2d_vec impulse, ga2d_vec world_point);
GA2D_API ga2d_result ga2d_body_apply_angular_impulse(ga2d_world *w, ga2d_body_id id, ga2d_real impulse_e12);

/* ----------------------------------------------------------------- shapes */
/* A body owns any number of shapes: each has its own geometry (in the
   body's frame), material, filter and user data, and is what collides.
   Shapes of one body never collide with each other.  The body's mass,
   centre and inertia are the exact sum over its shapes (parallel axes),
   refreshed when shapes come and go. */
GA2D_API ga2d_shape_id ga2d_shape_id_null(void);
GA2D_API int ga2d_shape_id_is_null(ga2d_shape_id id);
GA2D_API int ga2d_shape_id_equal(ga2d_shape_id a, ga2d_shape_id b);

typedef struct ga2d_shape_def {
    ga2d_real density;        /* kg/m^2; default 1 (0: no mass, as for a sensor) */
    ga2d_real friction;       /* default 0.6; mixes as sqrt(mu_a mu_b) */
    ga2d_real restitution;    /* default 0; mixes as the larger */
    ga2d_filter filter;       /* default: category 1, collides with all */
    void *user_data;
    int is_sensor;            /* detects overlaps (ga2d_world_sensor_events), never
                                 pushes and adds no mass; default 0 */
    int enable_sensor_events; /* sensors may see this shape; default 1 */
    int enable_pre_solve_events; /* its contacts go to the world's pre_solve; default 0 */
    int enable_hit_events;    /* its contacts report hits (ga2d_contact_events); default 0 */
    ga2d_real tangent_speed;  /* m/s: a conveyor belt: its surface moves this fast
                                 clockwise round its outline (a ground's top: to
                                 +x), and friction carries what touches it; default 0 */
    ga2d_real rolling_resistance; /* a round shape rolling on it feels a torque of
                                 at most this times its radius times the normal
                                 force (the larger of the two shapes'); default 0 */
    int internal_cookie;      /* set by ga2d_default_shape_def(); leave it */
} ga2d_shape_def;
GA2D_API ga2d_shape_def ga2d_default_shape_def(void);

/* Each returns the null id on failure (then the world is unchanged); the
   _checked forms say why: STALE_ID (the body), LOCKED (from a callback or
   a step), INVALID_ARGUMENT (NULL, a negative density, friction,
   restitution or radius, a type out of range), NOT_FINITE, TOO_LARGE
   (beyond GA2D_MAX_COORDINATE), the polygon's checks as
   ga2d_polygon_make's, DEGENERATE (a capsule whose ends coincide within
   64 eps of its size is a circle: make a circle; a segment of zero
   length; a shape too small to give a dynamic body a mass and inertia
   whose inverses are finite), MASS_OVERFLOW (the body's mass, centre,
   inertia or its centre's velocity, summed with the new shape, would not
   be finite: shapes each accepted can sum past the range of ga2d_real),
   OUT_OF_MEMORY.  A segment has no area: it goes on static and kinematic
   bodies (INVALID_ARGUMENT on a dynamic one). */
GA2D_API ga2d_shape_id ga2d_shape_create_circle(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_circle *c);
GA2D_API ga2d_shape_id ga2d_shape_create_capsule(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_capsule *c);
GA2D_API ga2d_shape_id ga2d_shape_create_polygon(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_polygon *p);
GA2D_API ga2d_shape_id ga2d_shape_create_segment(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_segment *s);
/* Any of the above from a geometry; *out gets the id (null on failure).
   A chain segment is INVALID_ARGUMENT here: chains make their own. */
GA2D_API ga2d_result ga2d_shape_create_checked(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def,
                                              const ga2d_geometry *g, ga2d_shape_id *out);
/* Destroys a shape (its contacts end without events, as a body's do);
   update_body_mass 0 keeps the body's mass as it was until the next
   shape change or ga2d_body_set_mass_data.  With update_body_mass, the
   sums without the shape are checked as a creation's are
   (MASS_OVERFLOW, nothing destroyed). */
GA2D_API ga2d_result ga2d_shape_destroy(ga2d_world *w, ga2d_shape_id id, int update_body_mass);
GA2D_API int ga2d_shape_is_valid(const ga2d_world *w, ga2d_shape_id id);
GA2D_API ga2d_body_id ga2d_shape_body(const ga2d_world *w, ga2d_shape_id id);   /* null if stale */
GA2D_API ga2d_shape_type ga2d_shape_get_type(const ga2d_world *w, ga2d_shape_id id); /* GA2D_SHAPE_TYPE_COUNT if stale */
/* The shape's geometry in its body's frame (zeroed if stale). */
GA2D_API ga2d_geometry ga2d_shape_geometry(const ga2d_world *w, ga2d_shape_id id);
GA2D_API void *ga2d_shape_user_data(const ga2d_world *w, ga2d_shape_id id);
GA2D_API ga2d_result ga2d_shape_set_friction(ga2d_world *w, ga2d_shape_id id, ga2d_real friction);
GA2D_API ga2d_result ga2d_shape_set_restitution(ga2d_world *w, ga2d_shape_id id, ga2d_real restitution);
GA2D_API ga2d_result ga2d_shape_set_filter(ga2d_world *w, ga2d_shape_id id, ga2d_filter f);
GA2D_API ga2d_filter ga2d_shape_filter(const ga2d_world *w, ga2d_shape_id id);
/* The shape's box in the broadphase (see ga2d_body_fat_aabb); after a
   step it holds the shape's tight box. */
GA2D_API ga2d_aabb ga2d_shape_fat_aabb(const ga2d_world *w, ga2d_shape_id id);
/* The shape's tight box where its body is now (zero for an invalid id). */
GA2D_API ga2d_aabb ga2d_shape_aabb(const ga2d_world *w, ga2d_shape_id id);
/* Up to `capacity` of a body's shapes, in creation order; returns how many it has. */
GA2D_API int ga2d_body_get_shapes(const ga2d_world *w, ga2d_body_id id, ga2d_shape_id *out, int capacity);

/* Terrain: a chain of one-sided segments (ga2d_chain_segment) through
   `points`, each knowing its neighbours, so bodies slide across the joins
   without catching.  A segment pushes only toward its left: a ground chain
   runs left to right; a loop wound counter-clockwise holds bodies inside
   it, one wound clockwise keeps them out.  An open chain's ends are
   rounded over as a lone segment's are.  On static and kinematic bodies
   only. */
typedef struct ga2d_chain_id { uint32_t index1; uint32_t generation; } ga2d_chain_id; /* zero: null */
typedef struct ga2d_chain_def {
    const ga2d_vec *points;   /* in the body's frame; copied */
    int count;                /* at least 2 (3 for a loop) */
    int is_loop;              /* the last point joins the first */
    ga2d_real friction;       /* default 0.6 */
    ga2d_real restitution;    /* default 0 */
    ga2d_filter filter;
    void *user_data;          /* each segment's */
    int internal_cookie;      /* set by ga2d_default_chain_def(); leave it */
} ga2d_chain_def;
GA2D_API ga2d_chain_def ga2d_default_chain_def(void);
/* The null id on failure, world unchanged; the checked form says why:
   TOO_FEW_POINTS (under 2, or 3 for a loop), REPEATED_POINTS (two
   consecutive points within 64 eps of their size), INVALID_ARGUMENT (NULL,
   a dynamic body, negative friction or restitution), NOT_FINITE,
   TOO_LARGE, MASS_OVERFLOW (see ga2d_shape_create_checked), STALE_ID,
   LOCKED, OUT_OF_MEMORY.  Every segment is checked as the snapshot loader
   checks it, so a world with the chain saves a snapshot that loads. */
GA2D_API ga2d_chain_id ga2d_chain_create(ga2d_world *w, ga2d_body_id body, const ga2d_chain_def *def);
GA2D_API ga2d_result ga2d_chain_create_checked(ga2d_world *w, ga2d_body_id body, const ga2d_chain_def *def, ga2d_chain_id *out);
/* Destroys the chain's segments (a chain segment cannot be destroyed on
   its own: ga2d_shape_destroy refuses it). */
GA2D_API ga2d_result ga2d_chain_destroy(ga2d_world *w, ga2d_chain_id id);
/* Up to `capacity` of the chain's segments in order; returns how many. */
GA2D_API int ga2d_chain_get_segments(const ga2d_world *w, ga2d_chain_id id, ga2d_shape_id *out, int capacity);

/* ----------------------------------------------------------------- joints */
/* A joint holds two bodies together: anchors given in each body's own
   frame, relative to its origin (ga2d_body_local_point turns a world
   point into one).  Joints are solved with the contacts in every substep
   (DESIGN section 11): rigid by default, a spring where asked for.  They
   join islands (a body hanging from another sleeps and wakes with it),
   are saved in snapshots, drawn by ga2d_world_draw, and a world without
   joints pays nothing for them. */
typedef struct ga2d_joint_id { uint32_t index1; uint32_t generation; } ga2d_joint_id; /* zero: null */
GA2D_API ga2d_joint_id ga2d_joint_id_null(void);
GA2D_API int ga2d_joint_id_is_null(ga2d_joint_id id);
GA2D_API int ga2d_joint_id_equal(ga2d_joint_id a, ga2d_joint_id b);

typedef enum ga2d_joint_type {
    GA2D_JOINT_DISTANCE,
    GA2D_JOINT_REVOLUTE,
    GA2D_JOINT_PRISMATIC,
    GA2D_JOINT_WELD,
    GA2D_JOINT_WHEEL,
    GA2D_JOINT_MOTOR,
    GA2D_JOINT_TYPE_COUNT
} ga2d_joint_type;

/* A hinge: B's anchor stays on A's, and B turns freely about it, or
   within [lower_angle, upper_angle] (radians, B's angle relative to A's
   less reference_angle), driven by a motor toward motor_speed (rad/s)
   with at most max_motor_torque (N m), or pulled toward the reference
   angle by a rotational spring of `hertz` and damping_ratio (hertz 0: no
   spring).  Defaults: anchors at both origins, everything off, the
   bodies' shapes do not collide with each other (collide_connected 0). */
typedef struct ga2d_revolute_joint_def {
    ga2d_body_id body_a, body_b;
    ga2d_vec local_anchor_a, local_anchor_b;
    int collide_connected;
    void *user_data;
    ga2d_real reference_angle;
    int enable_limit;
    ga2d_real lower_angle, upper_angle;
    int enable_motor;
    ga2d_real motor_speed, max_motor_torque;
    int enable_spring;
    ga2d_real hertz, damping_ratio;
    int internal_cookie;      /* set by ga2d_default_revolute_joint_def(); leave it */
} ga2d_revolute_joint_def;
GA2D_API ga2d_revolute_joint_def ga2d_default_revolute_joint_def(void);

/* The null id on failure (the world unchanged); the _checked form says
   why: INVALID_ARGUMENT (NULL, a joint between a body and itself, two
   bodies of which neither is dynamic, a negative max_motor_torque, hertz
   or damping_ratio, lower_angle above upper_angle when the limit is on),
   STALE_ID (either body), NOT_FINITE (any number), TOO_LARGE (an anchor
   beyond GA2D_MAX_COORDINATE), LOCKED (from a callback or a step),
   OUT_OF_MEMORY.  Creating a joint wakes both bodies; with
   collide_connected 0 their contacts end (no end event: they never touch
   again while joined). */
GA2D_API ga2d_result ga2d_revolute_joint_create_checked(ga2d_world *w, const ga2d_revolute_joint_def *def,
                                                        ga2d_joint_id *out);
GA2D_API ga2d_joint_id ga2d_revolute_joint_create(ga2d_world *w, const ga2d_revolute_joint_def *def);
/* Destroys a joint and wakes its bodies.  Destroying a body destroys its
   joints (their ids go stale). */
GA2D_API ga2d_result ga2d_joint_destroy(ga2d_world *w, ga2d_joint_id id);
GA2D_API int ga2d_joint_is_valid(const ga2d_world *w, ga2d_joint_id id);
GA2D_API ga2d_joint_type ga2d_joint_get_type(const ga2d_world *w, ga2d_joint_id id); /* TYPE_COUNT if stale */
GA2D_API ga2d_body_id ga2d_joint_body_a(const ga2d_world *w, ga2d_joint_id id);      /* null if stale */
GA2D_API ga2d_body_id ga2d_joint_body_b(const ga2d_world *w, ga2d_joint_id id);
GA2D_API void *ga2d_joint_user_data(const ga2d_world *w, ga2d_joint_id id);
GA2D_API int ga2d_joint_collide_connected(const ga2d_world *w, ga2d_joint_id id);
/* What the joint did to B in the last step (N and N m, world frame): the
   impulses of its last substep over the substep.  Zero if stale. */
GA2D_API ga2d_vec ga2d_joint_reaction_force(const ga2d_world *w, ga2d_joint_id id);
GA2D_API ga2d_real ga2d_joint_reaction_torque(const ga2d_world *w, ga2d_joint_id id);
/* B's angle relative to A's less the reference angle (radians, within
   (-pi, pi]), and B's spin relative to A's (rad/s). */
GA2D_API ga2d_real ga2d_revolute_joint_angle(const ga2d_world *w, ga2d_joint_id id);
GA2D_API ga2d_real ga2d_revolute_joint_speed(const ga2d_world *w, ga2d_joint_id id);
/* What a game changes at run time.  Each wakes the bodies; INVALID_ARGUMENT
   for a joint of another kind or a value as create refuses it, STALE_ID,
   NOT_FINITE, LOCKED. */
GA2D_API ga2d_result ga2d_revolute_joint_enable_motor(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_revolute_joint_set_motor_speed(ga2d_world *w, ga2d_joint_id id, ga2d_real speed);
GA2D_API ga2d_result ga2d_revolute_joint_set_max_motor_torque(ga2d_world *w, ga2d_joint_id id, ga2d_real torque);
GA2D_API ga2d_result ga2d_revolute_joint_enable_limit(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_revolute_joint_set_limits(ga2d_world *w, ga2d_joint_id id, ga2d_real lower, ga2d_real upper);
GA2D_API ga2d_result ga2d_revolute_joint_enable_spring(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_revolute_joint_set_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio);
GA2D_API ga2d_real ga2d_revolute_joint_motor_torque(const ga2d_world *w, ga2d_joint_id id); /* N m, last step */
/* A rod, rope or spring between the anchors: their distance held at
   `length` (m, > 0), or, with the limit on, kept within [min_length,
   max_length] (a rope: min 0; min equal to max holds it there, rigid,
   the spring aside); a spring of `hertz` and damping_ratio
   pulls it toward `length` (hertz 0: rigid); a motor drives the length's
   rate toward motor_speed (m/s) with at most max_motor_force (N).
   Defaults: length 1, limits 0 and 1e6 (off), everything else off. */
typedef struct ga2d_distance_joint_def {
    ga2d_body_id body_a, body_b;
    ga2d_vec local_anchor_a, local_anchor_b;
    int collide_connected;
    void *user_data;
    ga2d_real length;
    int enable_limit;
    ga2d_real min_length, max_length;
    int enable_spring;
    ga2d_real hertz, damping_ratio;
    int enable_motor;
    ga2d_real motor_speed, max_motor_force;
    int internal_cookie;      /* set by ga2d_default_distance_joint_def(); leave it */
} ga2d_distance_joint_def;
GA2D_API ga2d_distance_joint_def ga2d_default_distance_joint_def(void);
/* As the revolute create; INVALID_ARGUMENT also for a length not > 0, a
   negative min_length, min_length above max_length. */
GA2D_API ga2d_result ga2d_distance_joint_create_checked(ga2d_world *w, const ga2d_distance_joint_def *def,
                                                        ga2d_joint_id *out);
GA2D_API ga2d_joint_id ga2d_distance_joint_create(ga2d_world *w, const ga2d_distance_joint_def *def);
GA2D_API ga2d_real ga2d_distance_joint_current_length(const ga2d_world *w, ga2d_joint_id id); /* 0 if stale */
GA2D_API ga2d_result ga2d_distance_joint_set_length(ga2d_world *w, ga2d_joint_id id, ga2d_real length);
GA2D_API ga2d_result ga2d_distance_joint_enable_limit(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_distance_joint_set_length_range(ga2d_world *w, ga2d_joint_id id, ga2d_real min_length,
                                                          ga2d_real max_length);
GA2D_API ga2d_result ga2d_distance_joint_enable_spring(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_distance_joint_set_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio);
GA2D_API ga2d_result ga2d_distance_joint_enable_motor(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_distance_joint_set_motor_speed(ga2d_world *w, ga2d_joint_id id, ga2d_real speed);
GA2D_API ga2d_result ga2d_distance_joint_set_max_motor_force(ga2d_world *w, ga2d_joint_id id, ga2d_real force);

/* Glue: B held at its place and angle on A (reference_angle: B's angle
   less A's), rigid (hertz 0), or soft, a linear spring of linear_hertz
   and an angular one of angular_hertz with their damping ratios.
   Defaults: rigid. */
typedef struct ga2d_weld_joint_def {
    ga2d_body_id body_a, body_b;
    ga2d_vec local_anchor_a, local_anchor_b;
    int collide_connected;
    void *user_data;
    ga2d_real reference_angle;
    ga2d_real linear_hertz, angular_hertz, linear_damping_ratio, angular_damping_ratio;
    int internal_cookie;      /* set by ga2d_default_weld_joint_def(); leave it */
} ga2d_weld_joint_def;
GA2D_API ga2d_weld_joint_def ga2d_default_weld_joint_def(void);
GA2D_API ga2d_result ga2d_weld_joint_create_checked(ga2d_world *w, const ga2d_weld_joint_def *def, ga2d_joint_id *out);
GA2D_API ga2d_joint_id ga2d_weld_joint_create(ga2d_world *w, const ga2d_weld_joint_def *def);
GA2D_API ga2d_result ga2d_weld_joint_set_linear_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio);
GA2D_API ga2d_result ga2d_weld_joint_set_angular_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio);

/* Drives B toward a pose relative to A: B's anchor toward A's anchor
   plus linear_offset (in A's frame), B's angle toward A's plus
   angular_offset: each substep asks for the velocity that closes
   correction_factor of the gap (bias = factor x gap / h), with at most
   max_force (N) and max_torque (N m).  With A a static body and the
   offset set each frame to the pointer (ga2d_motor_joint_set_linear_offset),
   it is a mouse drag that cannot fling what it holds.  Defaults: offsets
   0, max_force 1, max_torque 1, correction_factor 0.3. */
typedef struct ga2d_motor_joint_def {
    ga2d_body_id body_a, body_b;
    ga2d_vec local_anchor_a, local_anchor_b;
    int collide_connected;
    void *user_data;
    ga2d_vec linear_offset;
    ga2d_real angular_offset, max_force, max_torque, correction_factor;
    int internal_cookie;      /* set by ga2d_default_motor_joint_def(); leave it */
} ga2d_motor_joint_def;
GA2D_API ga2d_motor_joint_def ga2d_default_motor_joint_def(void);
/* As the revolute create; INVALID_ARGUMENT also for a negative max_force
   or max_torque, a correction_factor outside [0, 1]; TOO_LARGE for an
   offset beyond GA2D_MAX_COORDINATE. */
GA2D_API ga2d_result ga2d_motor_joint_create_checked(ga2d_world *w, const ga2d_motor_joint_def *def, ga2d_joint_id *out);
GA2D_API ga2d_joint_id ga2d_motor_joint_create(ga2d_world *w, const ga2d_motor_joint_def *def);
GA2D_API ga2d_result ga2d_motor_joint_set_linear_offset(ga2d_world *w, ga2d_joint_id id, ga2d_vec offset);
GA2D_API ga2d_result ga2d_motor_joint_set_angular_offset(ga2d_world *w, ga2d_joint_id id, ga2d_real offset);
GA2D_API ga2d_result ga2d_motor_joint_set_max_force(ga2d_world *w, ga2d_joint_id id, ga2d_real force);
GA2D_API ga2d_result ga2d_motor_joint_set_max_torque(ga2d_world *w, ga2d_joint_id id, ga2d_real torque);

/* A slider: B moves along an axis fixed in A (local_axis_a, any length:
   it is made unit), its angle held to A's plus reference_angle; the
   translation (B's anchor from A's, along the axis, m) within [lower,
   upper] with the limit on, driven toward motor_speed (m/s) with at most
   max_motor_force (N), or pulled to 0 by a spring of `hertz` and
   damping_ratio.  Defaults: axis x, everything off. */
typedef struct ga2d_prismatic_joint_def {
    ga2d_body_id body_a, body_b;
    ga2d_vec local_anchor_a, local_anchor_b;
    int collide_connected;
    void *user_data;
    ga2d_vec local_axis_a;
    ga2d_real reference_angle;
    int enable_limit;
    ga2d_real lower_translation, upper_translation;
    int enable_motor;
    ga2d_real motor_speed, max_motor_force;
    int enable_spring;
    ga2d_real hertz, damping_ratio;
    int internal_cookie;      /* set by ga2d_default_prismatic_joint_def(); leave it */
} ga2d_prismatic_joint_def;
GA2D_API ga2d_prismatic_joint_def ga2d_default_prismatic_joint_def(void);
/* As the revolute create; INVALID_ARGUMENT also for an axis of length 0. */
GA2D_API ga2d_result ga2d_prismatic_joint_create_checked(ga2d_world *w, const ga2d_prismatic_joint_def *def,
                                                         ga2d_joint_id *out);
GA2D_API ga2d_joint_id ga2d_prismatic_joint_create(ga2d_world *w, const ga2d_prismatic_joint_def *def);
GA2D_API ga2d_real ga2d_prismatic_joint_translation(const ga2d_world *w, ga2d_joint_id id); /* m */
GA2D_API ga2d_real ga2d_prismatic_joint_speed(const ga2d_world *w, ga2d_joint_id id);       /* m/s */
GA2D_API ga2d_result ga2d_prismatic_joint_enable_limit(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_prismatic_joint_set_limits(ga2d_world *w, ga2d_joint_id id, ga2d_real lower, ga2d_real upper);
GA2D_API ga2d_result ga2d_prismatic_joint_enable_motor(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_prismatic_joint_set_motor_speed(ga2d_world *w, ga2d_joint_id id, ga2d_real speed);
GA2D_API ga2d_result ga2d_prismatic_joint_set_max_motor_force(ga2d_world *w, ga2d_joint_id id, ga2d_real force);
GA2D_API ga2d_result ga2d_prismatic_joint_enable_spring(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_prismatic_joint_set_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio);

/* A wheel on a suspension: B's anchor stays on a line through A's along
   local_axis_a (A's frame; made unit), held near it by a spring of
   `hertz` and damping_ratio (the suspension), within [lower, upper]
   with the limit on; B turns freely, driven toward motor_speed (rad/s,
   relative to A) with at most max_motor_torque (N m).  Defaults: axis y
   (up, for a car whose chassis is A), the spring on at 1 Hz, damping
   ratio 0.7, the rest off. */
typedef struct ga2d_wheel_joint_def {
    ga2d_body_id body_a, body_b;
    ga2d_vec local_anchor_a, local_anchor_b;
    int collide_connected;
    void *user_data;
    ga2d_vec local_axis_a;
    int enable_spring;
    ga2d_real hertz, damping_ratio;
    int enable_limit;
    ga2d_real lower_translation, upper_translation;
    int enable_motor;
    ga2d_real motor_speed, max_motor_torque;
    int internal_cookie;      /* set by ga2d_default_wheel_joint_def(); leave it */
} ga2d_wheel_joint_def;
GA2D_API ga2d_wheel_joint_def ga2d_default_wheel_joint_def(void);
/* As the prismatic create. */
GA2D_API ga2d_result ga2d_wheel_joint_create_checked(ga2d_world *w, const ga2d_wheel_joint_def *def, ga2d_joint_id *out);
GA2D_API ga2d_joint_id ga2d_wheel_joint_create(ga2d_world *w, const ga2d_wheel_joint_def *def);
GA2D_API ga2d_real ga2d_wheel_joint_translation(const ga2d_world *w, ga2d_joint_id id); /* m, along the axis */
GA2D_API ga2d_real ga2d_wheel_joint_motor_torque(const ga2d_world *w, ga2d_joint_id id); /* N m, last step */
GA2D_API ga2d_result ga2d_wheel_joint_enable_spring(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_wheel_joint_set_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio);
GA2D_API ga2d_result ga2d_wheel_joint_enable_limit(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_wheel_joint_set_limits(ga2d_world *w, ga2d_joint_id id, ga2d_real lower, ga2d_real upper);
GA2D_API ga2d_result ga2d_wheel_joint_enable_motor(ga2d_world *w, ga2d_joint_id id, int enable);
GA2D_API ga2d_result ga2d_wheel_joint_set_motor_speed(ga2d_world *w, ga2d_joint_id id, ga2d_real speed);
GA2D_API ga2d_result ga2d_wheel_joint_set_max_motor_torque(ga2d_world *w, ga2d_joint_id id, ga2d_real torque);

/* A world point in the body's frame, relative to its origin: an anchor.
   Zero for a stale id. */
GA2D_API ga2d_vec ga2d_body_local_point(const ga2d_world *w, ga2d_body_id id, ga2d_vec world_point);

/* -------------------------------------------------------------- collision */
/* Tolerances, in metres; a world scales them by its length_units_per_meter.
   Linear slop: the overlap the solver allows to keep contacts steady.
   Speculative distance: contact points this far apart are kept, so a fast
   body is caught before it overlaps. */
#define GA2D_LINEAR_SLOP 0.005
#define GA2D_SPECULATIVE_DISTANCE (4 * GA2D_LINEAR_SLOP)
#define GA2D_AABB_MARGIN 0.1

/* A contact point.  point: world position (midway between the two
   surfaces); anchor_a, anchor_b: the same point relative to body A's and
   body B's origins (world orientation), computed without subtracting large
   coordinates; separation < 0 is penetration; id names the features that
   made the point: bit 16 set when B's face is the reference, bits 8-15 A's
   feature and bits 0-7 B's feature, so the same contact keeps its id while
   the bodies move a little.  The impulses are the solver's, carried from
   step to step by id, or by place when the id changed but the point
   stayed (0 from ga2d_collide_polygons). */
typedef struct ga2d_manifold_point {
    ga2d_vec point;
    ga2d_vec anchor_a, anchor_b;
    ga2d_real separation;
    ga2d_real normal_impulse, tangent_impulse;
    uint32_t id;
    int persisted; /* warm started: the id was in the previous step's manifold too, or
                      a new id stands where a point of it lay (within half a slop) */
} ga2d_manifold_point;

/* normal: unit, world frame, from A to B.  count: 0, 1 or 2. */
typedef struct ga2d_manifold {
    ga2d_vec normal;
    int count;
    ga2d_manifold_point points[2];
} ga2d_manifold;

/* The contact manifold of polygon a placed by xa and polygon b placed by
   xb, keeping points up to GA2D_SPECULATIVE_DISTANCE apart (their radii
   included).  Returns the number of points (0: farther apart than that;
   *out then has count 0), or a negative -GA2D_ERR_* for bad input, with
   *out untouched: NULL, a polygon whose count is out of range or which
   ga2d_polygon_make could not have made (zero edges, normals not unit or
   not out of their edges: INVALID_ARGUMENT), a negative radius
   (INVALID_ARGUMENT), a rotor whose |q|^2 is off 1 by more than 1e-4
   (INVALID_ARGUMENT), a non-finite transform, vertex or radius
   (NOT_FINITE).  The normal is then unit within that rotor tolerance.
   Needs no world. */
GA2D_API int ga2d_collide_polygons(const ga2d_polygon *a, ga2d_transform xa, const ga2d_polygon *b,
                                   ga2d_transform xb, ga2d_manifold *out);
/* Any two shapes, as ga2d_collide_polygons: one point for a circle
   against anything; up to two for the others.  A capsule or segment whose
   ends coincide collides as a circle; a chain segment only with what is
   on its left (in front), and with normals its joins allow.  Bad input as
   there, plus a type out of range (INVALID_ARGUMENT).  Sizes and offsets
   whose squares overflow (past about 1e19 in float, 1e154 in double) are
   answered without promises of accuracy or of agreement between the two
   argument orders. */
GA2D_API int ga2d_collide_shapes(const ga2d_geometry *a, ga2d_transform xa, const ga2d_geometry *b, ga2d_transform xb,
                                 ga2d_manifold *out);
GA2D_API int ga2d_collide_shapes_scaled(const ga2d_geometry *a, ga2d_transform xa, const ga2d_geometry *b,
                                        ga2d_transform xb, ga2d_real units, ga2d_manifold *out);
/* The same with the tolerances of a world whose length unit is
   1/length_units_per_meter of a metre (slop, margin scaled by it). */
GA2D_API int ga2d_collide_polygons_scaled(const ga2d_polygon *a, ga2d_transform xa, const ga2d_polygon *b,
                                          ga2d_transform xb, ga2d_real length_units_per_meter, ga2d_manifold *out);

GA2D_API int ga2d_aabb_overlaps(ga2d_aabb a, ga2d_aabb b);   /* closed boxes */
GA2D_API int ga2d_aabb_contains(ga2d_aabb outer, ga2d_aabb inner);
GA2D_API ga2d_aabb ga2d_aabb_union(ga2d_aabb a, ga2d_aabb b);

GA2D_API ga2d_filter ga2d_default_filter(void);
GA2D_API int ga2d_should_collide(ga2d_filter a, ga2d_filter b);
GA2D_API ga2d_result ga2d_body_set_filter(ga2d_world *w, ga2d_body_id id, ga2d_filter f);
GA2D_API ga2d_filter ga2d_body_filter(const ga2d_world *w, ga2d_body_id id);
/* The body's box in the broadphase: all the body can reach in a step (its
   AABB swept along v dt), grown by GA2D_AABB_MARGIN (in world length
   units) or a quarter of the body's extent if that is less; re-fitted only
   when the body could leave it within the next step. */
GA2D_API ga2d_aabb ga2d_body_fat_aabb(const ga2d_world *w, ga2d_body_id id);

/* A contact between two shapes of two bodies, shape A's slot before
   shape B's; the manifold's normal points from A to B. */
typedef struct ga2d_contact_data {
    ga2d_body_id body_a, body_b;
    ga2d_manifold manifold;
    ga2d_shape_id shape_a, shape_b;
} ga2d_contact_data;

/* The bodies that began and ended touching in the last step.  The arrays
   are the world's: valid until the next step, snapshot load or world
   destroy (read them after the step, not from inside it).  An end event carries
   the last manifold that touched.  Destroying a body ends its contacts
   without an event. */
/* A hit: a contact with hit events whose points came together faster
   than the world's hit_event_threshold and started pushing this step (a
   point that pushed in the last step is not hit again): where (the
   fastest point), the normal (A to B) and the approach speed, taken as
   the step began, for sounds and damage.  One landing, one hit. */
typedef struct ga2d_contact_hit_event {
    ga2d_shape_id shape_a, shape_b;
    ga2d_vec point, normal;
    ga2d_real approach_speed;
} ga2d_contact_hit_event;

typedef struct ga2d_contact_events {
    const ga2d_contact_data *begin;
    int begin_count;
    const ga2d_contact_data *end;
    int end_count;
    const ga2d_contact_hit_event *hit;
    int hit_count;
} ga2d_contact_events;

/* Broadphase pairs: bodies whose fat AABBs overlap, that may collide (at
   least one dynamic; the filter allows it).  Each pair is a contact,
   touching when its manifold has points.  Copies up to `capacity` pairs
   (in the world's deterministic order) and returns how many there are. */
GA2D_API int ga2d_world_get_pairs(const ga2d_world *w, ga2d_contact_data *out, int capacity);
/* The same for touching contacts only. */
GA2D_API int ga2d_world_get_contacts(const ga2d_world *w, ga2d_contact_data *out, int capacity);
GA2D_API ga2d_contact_events ga2d_world_contact_events(const ga2d_world *w);

/* Sensors: at the end of each step every sensor shape finds the shapes
   that overlap it (touching counts) on other bodies, that are not
   sensors, allow sensor events, and pass the filters; what changed is
   reported here, begun and ended, in sensor then visitor slot order.
   Events are bookended: every begin gets its end, also when either shape
   or its body is destroyed (the end comes with the next step's events,
   and its ids are stale by then).  The arrays are the world's, valid
   until the next step, as the contact events. */
typedef struct ga2d_sensor_event { ga2d_shape_id sensor, visitor; } ga2d_sensor_event;
typedef struct ga2d_sensor_events {
    const ga2d_sensor_event *begin;
    int begin_count;
    const ga2d_sensor_event *end;
    int end_count;
} ga2d_sensor_events;
GA2D_API ga2d_sensor_events ga2d_world_sensor_events(const ga2d_world *w);
/* Up to `capacity` of a sensor's visitors now; returns how many it has. */
GA2D_API int ga2d_shape_get_sensor_overlaps(const ga2d_world *w, ga2d_shape_id sensor, ga2d_shape_id *out, int capacity);
/* Up to `capacity` of one body's touching contacts; returns how many.
   Each is turned to face out of the asked-for body: it is body_a (and
   shape_a), and the normal points away from it, so a ground check is
   normal.y < -cos(max slope) without flipping by hand.  (The world's own
   lists, ga2d_world_get_contacts and the events, keep the A-before-B
   order.) */
GA2D_API int ga2d_body_get_contacts(const ga2d_world *w, ga2d_body_id id, ga2d_contact_data *out, int capacity);

/* ---------------------------------------------------------------- queries */
/* A ray p + t (translation), t in [0, 1], and where it first enters a
   shape: point, the shape's outward unit normal there (a segment's: the
   side facing the ray's start) and the fraction t.  hit = 0: nothing in
   reach, and the rest is zero.  A ray that starts inside a shape (or on
   its boundary, within rounding) does not hit it, so a ray cast from a
   body's centre sees out of its own shapes; a ray along a segment's line
   does not hit it; a ray that grazes a corner or a circle's edge hits
   it.  A chain segment is one-sided, as in collision: a ray from behind
   it (its right) passes through.  The world-free casts leave shape and
   body null. */
typedef struct ga2d_ray_result {
    ga2d_shape_id shape;
    ga2d_body_id body;
    ga2d_vec point, normal;
    ga2d_real fraction;
    int hit;
} ga2d_ray_result;

/* A ray against one shape in its own frame; bad input (NULL, a value not
   finite, origin + translation not finite, a negative radius, a polygon ga2d_polygon_make could not have
   made, a translation of zero length) does not hit. */
GA2D_API ga2d_ray_result ga2d_ray_cast_circle(const ga2d_circle *c, ga2d_vec origin, ga2d_vec translation);
GA2D_API ga2d_ray_result ga2d_ray_cast_capsule(const ga2d_capsule *c, ga2d_vec origin, ga2d_vec translation);
/* radius > 0: the rounded polygon */
GA2D_API ga2d_ray_result ga2d_ray_cast_polygon(const ga2d_polygon *p, ga2d_vec origin, ga2d_vec translation);
/* one_sided: hit only from the left of point1 -> point2 (as a chain's) */
GA2D_API ga2d_ray_result ga2d_ray_cast_segment(const ga2d_segment *s, ga2d_vec origin, ga2d_vec translation,
                                              int one_sided);
/* Any shape placed by x, the ray in world coordinates.  NOT_FINITE for a
   value not finite (origin + translation too), INVALID_ARGUMENT for NULL, a zero translation or a
   shape ga2d_collide_shapes would refuse; *out untouched then. */
GA2D_API ga2d_result ga2d_ray_cast_shape(const ga2d_geometry *g, ga2d_transform x, ga2d_vec origin, ga2d_vec translation,
                                         ga2d_ray_result *out);

/* A convex point cloud grown by a radius, for distance, casts and time of
   impact: 1 point and a radius is a circle, 2 a capsule (or a segment
   with radius 0), 3 or more a polygon (its vertices; rounded by the
   radius).  ga2d_make_proxy copies up to GA2D_MAX_POLYGON_VERTICES
   points (more are cut off; count < 1 gives count 0, which nothing
   accepts); ga2d_shape_proxy_of makes the proxy of a shape. */
typedef struct ga2d_shape_proxy {
    ga2d_vec points[GA2D_MAX_POLYGON_VERTICES];
    int count;
    ga2d_real radius;
} ga2d_shape_proxy;
GA2D_API ga2d_shape_proxy ga2d_make_proxy(const ga2d_vec *points, int count, ga2d_real radius);
GA2D_API ga2d_shape_proxy ga2d_shape_proxy_of(const ga2d_geometry *g);

/* What GJK kept of its last simplex: pass the same cache to the next call
   for the same pair (zeroed at first) and it starts from there, which
   takes one or two iterations for bodies that moved a little. */
typedef struct ga2d_simplex_cache {
    int count;
    uint8_t index_a[3], index_b[3];
} ga2d_simplex_cache;

/* Closest points of two proxies, their radii included: point_a on A's
   surface, point_b on B's, normal the unit direction from A to B,
   distance >= 0 (0 when they touch or overlap: then both points are the
   middle of the closest points of the cores, and normal is 0 when the
   cores themselves overlap).  iterations: GJK's (at most
   GA2D_GJK_MAX_ITERATIONS).  Errors: INVALID_ARGUMENT for NULL, a count
   out of range, a negative radius or a rotor not unit; NOT_FINITE.
   Points and offsets whose squares overflow (past about 1e19 in float,
   1e154 in double) are answered here, and by the cast and time of impact
   below, without promises of accuracy or even of finite values; the
   world's shape queries refuse values beyond GA2D_MAX_COORDINATE. */
#define GA2D_GJK_MAX_ITERATIONS 32
typedef struct ga2d_distance_result {
    ga2d_vec point_a, point_b, normal;
    ga2d_real distance;
    int iterations;
} ga2d_distance_result;
GA2D_API ga2d_result ga2d_shape_distance(const ga2d_shape_proxy *a, ga2d_transform xa, const ga2d_shape_proxy *b,
                                         ga2d_transform xb, ga2d_simplex_cache *cache, ga2d_distance_result *out);

/* B swept along translation (world) without turning, against A: the
   first fraction in [0, 1] at which they come within GA2D_LINEAR_SLOP of
   touching (B's surface within one slop of A's), the point on A's surface
   and A's outward normal there (toward B).  Already that close at 0: a
   hit at 0 (the normal of the closest points; 0 if the cores overlap).
   No hit if they never come that close.  Errors as ga2d_shape_distance,
   plus NOT_FINITE for the translation. */
GA2D_API ga2d_result ga2d_shape_cast(const ga2d_shape_proxy *a, ga2d_transform xa, const ga2d_shape_proxy *b,
                                     ga2d_transform xb, ga2d_vec translation, ga2d_ray_result *out);

/* A body's motion over a step, for time of impact: its centre of mass
   (local_center in its own frame) goes from c1 to c2 and its angle from
   a1 to a2 (radians), both linearly in t in [0, 1]. */
typedef struct ga2d_sweep {
    ga2d_vec local_center;
    ga2d_vec c1, c2;
    ga2d_real a1, a2;
} ga2d_sweep;
GA2D_API ga2d_transform ga2d_sweep_transform(const ga2d_sweep *s, ga2d_real t);

typedef enum ga2d_toi_state {
    GA2D_TOI_SEPARATED,  /* never within the target over [0, t_max]: t = t_max */
    GA2D_TOI_HIT,        /* first within the target at t */
    GA2D_TOI_OVERLAPPED, /* already within the target at t = 0 */
    GA2D_TOI_GAVE_UP     /* the iteration cap: t is a time before any impact (safe to move to) */
} ga2d_toi_state;
typedef struct ga2d_toi_result { ga2d_toi_state state; ga2d_real t; int iterations; } ga2d_toi_result;
/* When two proxies, moving by their sweeps, first come within target of
   each other (their radii included; GA2D_LINEAR_SLOP is what the world
   uses) over t in [0, t_max]: conservative advancement, each step of t
   the distance over the fastest any point of A can approach any point of
   B (the centres' relative speed along the normal plus each |a2 - a1|
   times its farthest point's reach), so it never steps past an impact.
   It stops within GA2D_LINEAR_SLOP / 4 of the target, or after
   GA2D_TOI_MAX_ITERATIONS (GAVE_UP, t safe).  Errors as
   ga2d_shape_distance, and INVALID_ARGUMENT for a target < 0 or t_max
   outside (0, 1]. */
#define GA2D_TOI_MAX_ITERATIONS 64
GA2D_API ga2d_result ga2d_time_of_impact(const ga2d_shape_proxy *a, const ga2d_sweep *sa, const ga2d_shape_proxy *b,
                                         const ga2d_sweep *sb, ga2d_real target, ga2d_real t_max, ga2d_toi_result *out);


/* World queries visit the broadphase trees, so they touch only the shapes
   whose boxes the query's box meets (counters.query_nodes and
   query_shapes say how many, for the last query), allocate nothing, and
   change nothing but those two counters.  A shape is seen when
   ga2d_should_collide(filter, its filter) holds (ga2d_default_filter()
   sees every shape); sensors are never seen.  Each is refused with LOCKED
   from inside a step, a callback of the world's (force, pre-solve, draw,
   allocator) or another query's callback: the world is locked while a
   query runs, so its callback can read the world but not change it.
   Errors: INVALID_ARGUMENT for a NULL world or callback or a zero
   translation, NOT_FINITE for a value not finite; the shape queries
   also TOO_LARGE for a proxy point or radius, x's position or a cast's
   end (x.p + translation) beyond GA2D_MAX_COORDINATE, as a shape's or a
   body's would be. */

/* The closest hit along origin + t translation, t in [0, 1] (the null
   shape and hit 0 for none, or on any error). */
GA2D_API ga2d_ray_result ga2d_world_cast_ray_closest(const ga2d_world *w, ga2d_vec origin, ga2d_vec translation,
                                                     ga2d_filter filter);
GA2D_API ga2d_result ga2d_world_cast_ray_closest_checked(const ga2d_world *w, ga2d_vec origin, ga2d_vec translation,
                                                         ga2d_filter filter, ga2d_ray_result *out);
/* Every hit, each shape's first crossing, in the trees' order (not by
   distance).  The callback returns how to go on: a negative value ignores
   this shape (the ray goes on as before), 0 stops, a fraction f in
   (0, 1] clips the ray to origin + f translation (return the hit's
   fraction to look for a closer one only; 1 to see every hit). */
typedef ga2d_real ga2d_cast_fn(ga2d_shape_id shape, ga2d_vec point, ga2d_vec normal, ga2d_real fraction, void *context);
GA2D_API ga2d_result ga2d_world_cast_ray(const ga2d_world *w, ga2d_vec origin, ga2d_vec translation, ga2d_filter filter,
                                         ga2d_cast_fn *fn, void *context);
/* The callback gets each shape found; returning 0 stops the query. */
typedef int ga2d_overlap_fn(ga2d_shape_id shape, void *context);
/* Shapes whose bounding box (tight, not the broadphase's fat one)
   overlaps box, touching included. */
GA2D_API ga2d_result ga2d_world_overlap_aabb(const ga2d_world *w, ga2d_aabb box, ga2d_filter filter, ga2d_overlap_fn *fn,
                                             void *context);
/* Shapes that contain point, their boundary included (segments and chain
   segments have no inside: never). */
GA2D_API ga2d_result ga2d_world_overlap_point(const ga2d_world *w, ga2d_vec point, ga2d_filter filter,
                                              ga2d_overlap_fn *fn, void *context);
/* Shapes that touch or overlap proxy placed by x (its radius included;
   ga2d_shape_proxy_of makes one of a shape).  Chain segments count as
   two-sided here. */
GA2D_API ga2d_result ga2d_world_overlap_shape(const ga2d_world *w, const ga2d_shape_proxy *proxy, ga2d_transform x,
                                              ga2d_filter filter, ga2d_overlap_fn *fn, void *context);
/* proxy placed by x swept along translation: each shape it would come
   within a slop of (ga2d_shape_cast: the point on that shape, its normal
   toward the proxy, the fraction), with the callback protocol of
   ga2d_world_cast_ray.  A shape already that close at the start is hit
   at 0.  The building block of a character controller: move to the
   closest fraction, then slide along the normal. */
GA2D_API ga2d_result ga2d_world_cast_shape(const ga2d_world *w, const ga2d_shape_proxy *proxy, ga2d_transform x,
                                           ga2d_vec translation, ga2d_filter filter, ga2d_cast_fn *fn, void *context);

/* The live bodies, in id index order: up to capacity ids into ids (NULL
   for none); returns how many there are. */
GA2D_API int ga2d_world_body_count(const ga2d_world *w);
GA2D_API int ga2d_world_get_bodies(const ga2d_world *w, ga2d_body_id *ids, int capacity);

/* ------------------------------------------------------------- debug draw */
/* Colours (0xRRGGBB) that say a body's state. */
#define GA2D_COLOR_STATIC 0x7FB27Fu
#define GA2D_COLOR_KINEMATIC 0x7F7FE5u
#define GA2D_COLOR_AWAKE 0xE59E4Cu
#define GA2D_COLOR_ASLEEP 0x9E9E9Eu
#define GA2D_COLOR_CONTACT 0xE53F3Fu
#define GA2D_COLOR_AABB 0xBF3FBFu
#define GA2D_COLOR_JOINT 0x4CB2E5u

/* What ga2d_world_draw hands a renderer: any callback may be NULL, and the
   switches choose what is drawn.  A shape comes with its body's id (and a
   polygon with its body's placement, so a renderer can keep its shapes
   across frames); a polygon's pointer is valid during that call only. */
typedef struct ga2d_debug_draw {
    void (*polygon)(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *context);
    void (*segment)(ga2d_vec a, ga2d_vec b, uint32_t color, void *context);
    void (*point)(ga2d_vec p, ga2d_real size, uint32_t color, void *context);
    /* a contact point: where, its normal (from body A to body B) and separation */
    void (*contact)(ga2d_vec p, ga2d_vec normal, ga2d_real separation, uint32_t color, void *context);
    void (*aabb)(ga2d_aabb box, uint32_t color, void *context);
    /* a circle shape: its centre, radius and the body's x axis (to show it
       turn); a capsule: its two centres and radius.  A segment comes to
       `segment`; a polygon's radius, when it has one, rounds it. */
    void (*circle)(ga2d_body_id id, ga2d_vec center, ga2d_real radius, ga2d_vec axis, uint32_t color, void *context);
    void (*capsule)(ga2d_body_id id, ga2d_vec center1, ga2d_vec center2, ga2d_real radius, uint32_t color, void *context);
    int draw_bodies;     /* default 1 */
    int draw_contacts;   /* default 0 */
    int draw_aabbs;      /* default 0: the broadphase's fat boxes */
    int draw_centers;    /* default 0: centres of mass, as points */
    int draw_joints;     /* default 1: each joint's anchors, and the line
                            from A's centre to its anchor, to B's anchor,
                            to B's centre */
    void *context;
} ga2d_debug_draw;

GA2D_API ga2d_debug_draw ga2d_default_debug_draw(void);
/* Calls the callbacks for every live body (in slot order) and, when asked,
   every touching contact point, fat box and centre.  Read-only: refused
   (LOCKED) from inside a step or any callback, and the world is locked
   while the callbacks run, so from them every change (creating,
   destroying, setting, stepping, loading) is refused with LOCKED and the
   getters read the world as it is.  ga2d_world_destroy from a callback
   ends the drawing there (no callback comes after it) and frees the world
   when the draw returns. */
GA2D_API ga2d_result ga2d_world_draw(const ga2d_world *w, const ga2d_debug_draw *draw);

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
#include <stdlib.h>
#include <string.h>

#ifndef GA2D_ASSERT
#include <assert.h>
#define GA2D_ASSERT(c) assert(c)
#endif

#ifdef GA2D_DOUBLE
#define GA2D__EPS DBL_EPSILON
#define GA2D__MAX DBL_MAX
#define GA2D__MIN_NORMAL DBL_MIN
#define GA2D__SQRT(x) sqrt(x)
#define GA2D__SIN(x) sin(x)
#define GA2D__COS(x) cos(x)
#define GA2D__ATAN2(y, x) atan2(y, x)
#define GA2D__FABS(x) fabs(x)
#else
#define GA2D__EPS FLT_EPSILON
#define GA2D__MAX FLT_MAX
#define GA2D__MIN_NORMAL FLT_MIN
#define GA2D__SQRT(x) sqrtf(x)
#define GA2D__SIN(x) sinf(x)
#define GA2D__COS(x) cosf(x)
#define GA2D__ATAN2(y, x) atan2f(y, x)
#define GA2D__FABS(x) fabsf(x)
#endif
#define GA2D__R(x) ((ga2d_real)(x))
#define GA2D__PI GA2D__R(3.14159265358979323846)
/* The caps on motion in ga2d_real (GA2D_MAX_LINEAR_SPEED is in m/s, times
   length_units_per_meter where used) */
#define GA2D__MAX_SPEED GA2D__R(GA2D_MAX_LINEAR_SPEED)
#define GA2D__MAX_TURN GA2D__R(GA2D_MAX_ROTATION)

/* The solver's and sleep's fixed numbers, with their units (lengths in
   metres are scaled by length_units_per_meter where used). */
#define GA2D__SLEEP_SPEED GA2D__R(0.05)         /* m/s: a body slower than this rests */
#define GA2D__TIME_TO_SLEEP GA2D__R(0.5)        /* s: an island at rest this long sleeps */
#define GA2D__BAUMGARTE GA2D__R(0.2)            /* of the overlap past slop, fed back per substep */
#define GA2D__NGS_FRACTION GA2D__R(0.2)         /* of the overlap past slop, moved per NGS pass */
#define GA2D__NGS_MAX_MOVE GA2D__R(0.2)         /* m: the most an NGS pass moves a point */
#define GA2D__RESTITUTION_PASSES 32             /* restitution's passes, at most, a step */
#define GA2D__ADVANCE_ITERATIONS 16             /* restitution's conservative advancement, at most */
#define GA2D__COLOURS 32                        /* the solver's colours (a bit each); more constraints on a pair of bodies overflow */
#define GA2D__HERTZ_CAP GA2D__R(0.25)           /* contact_hertz's cap, of the substep rate */
#define GA2D__DRAW_CENTER_SIZE GA2D__R(0.05)    /* m: debug draw's centre of mass marker */
#define GA2D__JOINT_HERTZ GA2D__R(60)           /* Hz: a rigid joint's position feedback, a spring's */
#define GA2D__JOINT_DAMPING_RATIO GA2D__R(2)    /* and its damping ratio */

/* Helpers that run once per body or contact point and pass, hundreds of
   thousands of times a step: inlined into their callers (the solver's
   keep the lanes in registers across them). */
#if defined(__GNUC__) || defined(__clang__)
#define GA2D__HOT inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define GA2D__HOT __forceinline
#else
#define GA2D__HOT inline
#endif

/* A hint that *p will be read or written soon (a stage that walks one
   array and reads or writes records of another in its order, each a cache
   miss in a large world: the miss starts a few records early).  Nothing
   without GCC's builtin; it changes no result. */
#if defined(__GNUC__) || defined(__clang__)
#define GA2D__PREFETCH_READ(p) __builtin_prefetch((p), 0)
#define GA2D__PREFETCH_WRITE(p) __builtin_prefetch((p), 1)
#else
#define GA2D__PREFETCH_READ(p) ((void)0)
#define GA2D__PREFETCH_WRITE(p) ((void)0)
#endif
/* How many groups or records ahead a stage asks for them. */
#define GA2D__PREFETCH_AHEAD 16

#ifdef __cplusplus
extern "C" {
#endif

/* ================================================================ algebra */
/* ---------------------------------------------------------------- results */
GA2D_API const char *ga2d_result_string(ga2d_result r)
{
    switch (r) {
    case GA2D_OK: return "ok";
    case GA2D_ERR_INVALID_ARGUMENT: return "invalid argument";
    case GA2D_ERR_NOT_FINITE: return "a value is NaN or infinite";
    case GA2D_ERR_TOO_FEW_POINTS: return "fewer than 3 distinct points";
    case GA2D_ERR_TOO_MANY_POINTS: return "more than GA2D_MAX_POLYGON_VERTICES points";
    case GA2D_ERR_TOO_LARGE: return "beyond a documented bound (coordinate, time step or gravity)";
    case GA2D_ERR_REPEATED_POINTS: return "two points coincide within the tolerance";
    case GA2D_ERR_COLLINEAR_POINTS: return "points are collinear within the tolerance";
    case GA2D_ERR_DEGENERATE: return "zero or near-zero area";
    case GA2D_ERR_CLOCKWISE: return "vertices are clockwise (want counter-clockwise)";
    case GA2D_ERR_NOT_CONVEX: return "polygon is not strictly convex";
    case GA2D_ERR_NOT_INVERTIBLE: return "multivector is not invertible";
    case GA2D_ERR_OUT_OF_MEMORY: return "out of memory";
    case GA2D_ERR_STALE_ID: return "id is stale or forged";
    case GA2D_ERR_LOCKED: return "the world is locked while it steps";
    case GA2D_ERR_BAD_SNAPSHOT: return "snapshot is truncated, corrupted or from another version or build";
    case GA2D_ERR_BUFFER_TOO_SMALL: return "buffer too small for the snapshot";
    case GA2D_ERR_MASS_OVERFLOW: return "the body's mass, centre or inertia summed over its shapes would not be finite";
    case GA2D_RESULT_COUNT: break;
    }
    return "unknown result";
}

static int ga2d__finite(ga2d_real x) { return x - x == x - x; } /* false for NaN, Inf */
static int ga2d__finite_vec(ga2d_vec v) { return ga2d__finite(v.x) && ga2d__finite(v.y); }

/* The most slots a world holds: keeps every byte count far from overflow. */
#define GA2D__MAX_BODIES (1 << 26)

static void *ga2d__alloc(const ga2d_allocator *a, size_t size)
{
    return a->alloc ? a->alloc(size, a->ctx) : malloc(size);
}

static void ga2d__free(const ga2d_allocator *a, void *p, size_t size)
{
    if (!p) return;
    if (a->free) a->free(p, size, a->ctx);
    else free(p);
}

/* Frees an array of cap elements. */
#define GA2D__FREE_ARRAY(a, arr, cap) ga2d__free(a, arr, (size_t)(cap) * sizeof *(arr))

/* Grows *arr to hold `need` elements.  The new block is allocated before
   the old one is released, so a failure (returns 0) changes nothing. */
static int ga2d__grow(const ga2d_allocator *a, void **arr, int *cap, int need, size_t elem)
{
    int newcap = *cap ? *cap : 16, oldcap = *cap;
    void *p, *old = *arr;
    if (need <= *cap) return 1;
    if (need > GA2D__MAX_BODIES) return 0;
    while (newcap < need) newcap *= 2;
    p = ga2d__alloc(a, (size_t)newcap * elem);
    if (!p) return 0;
    if (old) memcpy(p, old, (size_t)oldcap * elem);
    /* the new block is in place before the old one goes: a free hook that
       reads the world sees whole arrays */
    *arr = p;
    *cap = newcap;
    ga2d__free(a, old, (size_t)oldcap * elem);
    return 1;
}

/* Two arrays of one kind trade places, capacities with them (a list
   rebuilt into the spare one becomes the list). */
static void ga2d__swap_arrays(void **a, int *cap_a, void **b, int *cap_b)
{
    void *p = *a;
    int cap = *cap_a;
    *a = *b;
    *cap_a = *cap_b;
    *b = p;
    *cap_b = cap;
}



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
/* a^-1 b inlined where every contact asks for it each step (the carried
   manifolds); the public one is this. */
static GA2D__HOT ga2d_transform ga2d__inv_mul(ga2d_transform a, ga2d_transform b)
{
    return ga2d_transform_make(ga2d_transform_apply_inv(a, b.p), ga2d_rotor_mul(ga2d_rotor_inverse(a.q), b.q));
}
GA2D_API ga2d_transform ga2d_transform_inv_mul(ga2d_transform a, ga2d_transform b) { return ga2d__inv_mul(a, b); }

/* ------------------------------------------------------------------ turns */
/* exp(a e12) = cos a + sin a e12, without libm so that a step gives the
   same bits on every platform.  |a| <= pi/4 (the usual turn per substep)
   goes straight to the series; larger a is first reduced by k quarter
   turns (Cody-Waite: pi/2 in two parts), and e12^k is exact:
   (c, s) -> (-s, c).  The series (Horner, reciprocal factorials) stop where
   the next term at pi/4 is below half an ulp: r^9 / r^10 in float,
   r^17 / r^18 in double. */
/* exp(r e12) for |r| <= pi/4: the polynomials of cos and sin there */
static GA2D__HOT ga2d_rotor ga2d__exp_e12_near(ga2d_real r)
{
    ga2d_real r2 = r * r, c, s;
#ifdef GA2D_DOUBLE
    c = 1 + r2 * (-1.0 / 2 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800 +
        r2 * (1.0 / 479001600 + r2 * (-1.0 / 87178291200.0 + r2 * (1.0 / 20922789888000.0))))))));
    s = r * (1 + r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 + r2 * (-1.0 / 39916800 +
        r2 * (1.0 / 6227020800.0 + r2 * (-1.0 / 1307674368000.0 + r2 * (1.0 / 355687428096000.0)))))))));
#else
    c = 1 + r2 * (-1.0f / 2 + r2 * (1.0f / 24 + r2 * (-1.0f / 720 + r2 * (1.0f / 40320))));
    s = r * (1 + r2 * (-1.0f / 6 + r2 * (1.0f / 120 + r2 * (-1.0f / 5040 + r2 * (1.0f / 362880)))));
#endif
    return ga2d__rotor(c, s);
}

/* exp(a e12) past pi/4: a less its nearest multiple k of pi/2 (in two
   parts, so the difference is exact), then turned by k quarters. */
static ga2d_rotor ga2d__exp_e12_far(ga2d_real a)
{
#ifdef GA2D_DOUBLE
    const ga2d_real pio2_hi = 1.5707963267341256, pio2_lo = 6.077100506506192e-11; /* hi: 33 bits */
#else
    const ga2d_real pio2_hi = 1.5707963705062866f, pio2_lo = -4.371139000186243e-08f; /* float pi/2 and the rest */
#endif
    ga2d_real k, t;
    ga2d_rotor e;
    long quarter;
    if (!ga2d__finite(a)) return ga2d__rotor(a - a, a - a); /* NaN: the step reports it */
    if (GA2D__FABS(a) > GA2D__R(1e6)) a = (ga2d_real)fmod((double)a, 6.283185307179586); /* exact */
    k = (ga2d_real)floor((double)(a * GA2D__R(0.63661977236758134) + GA2D__R(0.5)));
    e = ga2d__exp_e12_near((a - k * pio2_hi) - k * pio2_lo);
    for (quarter = (long)k & 3; quarter > 0; --quarter) { t = e.c; e.c = -e.s; e.s = t; }
    return e;
}

/* The turns of a substep are small: the near case inline. */
static GA2D__HOT ga2d_rotor ga2d__exp_e12(ga2d_real a)
{
    if (!(GA2D__FABS(a) <= GA2D__R(0.78539816339744831))) return ga2d__exp_e12_far(a);
    return ga2d__exp_e12_near(a);
}

/* q turned by `angle`: exactly, q exp(angle e12) followed by one Newton
   step toward |q| = 1 (r (3 - |r|^2)/2 takes a norm of 1 + d to 1 + O(d^2),
   so rounding never accumulates); or to first order, q (1 + angle e12)
   renormalized, which turns by atan(angle) instead of angle. */
static GA2D__HOT ga2d_rotor ga2d__turn(ga2d_rotor q, ga2d_real angle, ga2d_rotation_update mode)
{
    ga2d_rotor r;
    ga2d_real k;
    if (mode == GA2D_ROTATION_LINEAR) {
        r = ga2d__rotor(q.c - angle * q.s, q.s + angle * q.c);
        k = 1 / GA2D__SQRT(r.c * r.c + r.s * r.s);
        /* a turn so large that |r|^2 overflows (an NGS fix or RK4 stage on
           a body of tiny inertia) gave k = 0, the zero rotor: measure it
           scaled instead (NaN still passes through, for the step to see) */
        if (k == 0 && ga2d__finite(r.c) && ga2d__finite(r.s)) return ga2d_rotor_normalize(r);
    } else {
        r = ga2d_rotor_mul(q, ga2d__exp_e12(angle));
        k = (3 - (r.c * r.c + r.s * r.s)) / 2;
    }
    return ga2d__rotor(r.c * k, r.s * k);
}

/* =============================================================== geometry */
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
    /* so small that 1e-5 L^2 is not a normal number: the wedges underflow,
       no area can be told (and the mass would divide by a subnormal one);
       or below GA2D_MIN_EXTENT */
    if (!(2 * GA2D__POLY_MIN_AREA_RATIO * L * L >= GA2D__MIN_NORMAL) || !(L >= GA2D_MIN_EXTENT)) return GA2D_ERR_DEGENERATE;
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

/* The hull is wrapped as Andrew's two monotone chains, without sorting:
   the lower chain from the lexicographically smallest point (least x, then
   least y) to the largest, the upper chain back.  Each step looks only at
   points lexicographically after p (lower) or before it (upper), so every
   step makes progress and a chain ends within n steps whatever rounding
   does to the comparisons (a wrap with tolerances in its choices can
   cycle when a cloud's features are near tol).  The candidates'
   directions lie in one half-plane, where the wedge orders them; the most
   clockwise wins, and of points on one line the farthest, so points on an
   edge go.  Directions are compared scaled to a largest component of 1:
   the wedge of two tiny vectors (1e-35 apart in float) would underflow to
   0 and order nothing.  -1 when p ends its chain. */
static int ga2d__lex_less(ga2d_vec a, ga2d_vec b)
{
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

static ga2d_vec ga2d__direction(ga2d_vec d)
{
    ga2d_real ax = GA2D__FABS(d.x), ay = GA2D__FABS(d.y), m = ax > ay ? ax : ay;
    return ga2d_vec_make(d.x / m, d.y / m);
}

static int ga2d__hull_step(const ga2d_vec *pts, int n, ga2d_vec p, int upper)
{
    int q = -1, r;
    ga2d_vec uq = ga2d_vec_make(0, 0);
    ga2d_real lq = 0;
    for (r = 0; r < n; ++r) {
        ga2d_vec d, u;
        ga2d_real w, l;
        if (upper ? !ga2d__lex_less(pts[r], p) : !ga2d__lex_less(p, pts[r])) continue;
        d = ga2d_vec_sub(pts[r], p);
        if (d.x == 0 && d.y == 0) continue; /* apart by less than rounding */
        u = ga2d__direction(d);
        l = ga2d_vec_length(d);
        w = ga2d_wedge(uq, u);
        /* w == 0: one line, the farther point wins; or nearly opposite
           directions at the half-plane's two ends (the wedge rounded to
           0), where the one nearer its start (straight down for the
           lower chain, up for the upper) is the more clockwise */
        if (q < 0 || w < 0 || (w == 0 && (ga2d_dot(uq, u) > 0 ? l > lq : upper ? u.y > uq.y : u.y < uq.y))) {
            q = r;
            uq = u;
            lq = l;
        }
    }
    return q;
}

/* Can hull vertex v go, its neighbours a and b then joined by one edge?
   When v is within tol of the line a->b and no input point would lie more
   than 2 tol outside (right of) it: dropping vertices one after another
   would otherwise let the points dropped before drift out by up to tol
   each time.  Within tol/4 (ga2d_polygon_make's collinearity) it goes. */
static int ga2d__hull_drop(const ga2d_vec *pts, int n, ga2d_vec a, ga2d_vec v, ga2d_vec b, ga2d_real tol)
{
    ga2d_vec e = ga2d_vec_sub(b, a);
    ga2d_real len = ga2d_vec_length(e), d;
    int i;
    if (len == 0) return 0; /* a and b are one point: a segment's far end stays */
    d = ga2d__line_distance(a, b, v);
    if (d <= tol / 4) return 1;
    if (d > tol) return 0;
    for (i = 0; i < n; ++i)
        if (ga2d_wedge(e, ga2d_vec_sub(pts[i], a)) < -2 * tol * len) return 0;
    return 1;
}

GA2D_API ga2d_result ga2d_polygon_hull(const ga2d_vec *pts, int n, ga2d_polygon *out)
{
    /* room for both chains' vertices before the last drops */
    enum { CAP = 2 * GA2D_MAX_POLYGON_VERTICES + 4 };
    ga2d_vec hull[CAP];
    ga2d_real L, tol;
    ga2d_result r;
    int i, h = 0, start = 0, p, upper;
    if (!out || (n > 0 && !pts) || n < 0) return GA2D_ERR_INVALID_ARGUMENT;
    r = ga2d__check_points(pts, n, &L);
    if (r != GA2D_OK) return r;
    /* as in ga2d_polygon_make: too small for any area to be told, or
       below GA2D_MIN_EXTENT */
    if (L > 0 && (!(2 * GA2D__POLY_MIN_AREA_RATIO * L * L >= GA2D__MIN_NORMAL) || !(L >= GA2D_MIN_EXTENT)))
        return GA2D_ERR_DEGENERATE;
    tol = 4 * GA2D__POLY_REL_TOL * L;
    for (i = 1; i < n; ++i)
        if (ga2d__lex_less(pts[i], pts[start])) start = i;
    for (i = 0; i < n && ga2d_vec_length(ga2d_vec_sub(pts[i], pts[start])) <= tol; ++i) {}
    if (i == n) return GA2D_ERR_TOO_FEW_POINTS; /* all points weld to one */
    hull[h++] = pts[start];
    p = start;
    for (upper = 0; upper < 2; ++upper) {
        int q;
        while ((q = ga2d__hull_step(pts, n, pts[p], upper)) >= 0) {
            /* a vertex within tol of the line past it goes at once, so
               that near-duplicates and points on an edge never fill the
               array */
            while (h >= 2 && ga2d__hull_drop(pts, n, hull[h - 2], hull[h - 1], pts[q], tol)) --h;
            if (h == CAP) return GA2D_ERR_TOO_MANY_POINTS;
            hull[h++] = pts[q];
            p = q;
        }
    }
    --h; /* the upper chain ended where the lower began */
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
        if (ga2d__hull_drop(pts, n, hull[(i + h - 1) % h], hull[i], hull[(i + 1) % h], tol)) {
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

/* The box's makers share one: half-extents hw x hh, core shrunk by r. */
GA2D_API ga2d_result ga2d_polygon_rounded_box_checked(ga2d_real hw, ga2d_real hh, ga2d_real r, ga2d_polygon *out)
{
    ga2d_polygon poly;
    ga2d_real cx, cy;
    if (!out) return GA2D_ERR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    if (!ga2d__finite(hw) || !ga2d__finite(hh) || !ga2d__finite(r)) return GA2D_ERR_NOT_FINITE;
    if (!(hw > 0 && hh > 0 && r >= 0 && hw > r && hh > r)) return GA2D_ERR_INVALID_ARGUMENT;
    if (hw > GA2D_MAX_COORDINATE || hh > GA2D_MAX_COORDINATE) return GA2D_ERR_TOO_LARGE;
    cx = hw - r;
    cy = hh - r;
    memset(&poly, 0, sizeof poly);
    poly.count = 4;
    poly.vertices[0] = ga2d_vec_make(-cx, -cy);
    poly.vertices[1] = ga2d_vec_make(cx, -cy);
    poly.vertices[2] = ga2d_vec_make(cx, cy);
    poly.vertices[3] = ga2d_vec_make(-cx, cy);
    poly.normals[0] = ga2d_vec_make(0, -1);
    poly.normals[1] = ga2d_vec_make(1, 0);
    poly.normals[2] = ga2d_vec_make(0, 1);
    poly.normals[3] = ga2d_vec_make(-1, 0);
    poly.radius = r;
    if (r > 0) {
        /* a core too thin for ga2d_polygon_make could not become a shape */
        ga2d_polygon check;
        ga2d_result res = ga2d_polygon_make(poly.vertices, 4, &check);
        if (res != GA2D_OK) return res;
    }
    *out = poly;
    return GA2D_OK;
}

GA2D_API ga2d_polygon ga2d_polygon_rounded_box(ga2d_real hw, ga2d_real hh, ga2d_real r)
{
    ga2d_polygon poly;
    ga2d_polygon_rounded_box_checked(hw, hh, r, &poly);
    return poly;
}

GA2D_API ga2d_polygon ga2d_polygon_box(ga2d_real hw, ga2d_real hh) { return ga2d_polygon_rounded_box(hw, hh, 0); }

GA2D_API ga2d_result ga2d_polygon_regular_checked(int n, ga2d_real radius, ga2d_polygon *out)
{
    ga2d_vec pts[GA2D_MAX_POLYGON_VERTICES];
    ga2d_result r;
    int i;
    if (!out) return GA2D_ERR_INVALID_ARGUMENT;
    memset(out, 0, sizeof *out);
    if (n < 3) return GA2D_ERR_TOO_FEW_POINTS;
    if (n > GA2D_MAX_POLYGON_VERTICES) return GA2D_ERR_TOO_MANY_POINTS;
    if (!ga2d__finite(radius)) return GA2D_ERR_NOT_FINITE;
    if (!(radius > 0)) return GA2D_ERR_INVALID_ARGUMENT;
    for (i = 0; i < n; ++i) {
        /* angles from double, so float builds place vertices as well as
           float can hold them */
        double t = 2.0 * 3.14159265358979323846 * (double)i / (double)n;
        pts[i] = ga2d_vec_make(radius * (ga2d_real)cos(t), radius * (ga2d_real)sin(t));
    }
    r = ga2d_polygon_make(pts, n, out);
    if (r != GA2D_OK) memset(out, 0, sizeof *out);
    return r;
}

GA2D_API ga2d_polygon ga2d_polygon_regular(int n, ga2d_real radius)
{
    ga2d_polygon poly;
    ga2d_polygon_regular_checked(n, radius, &poly);
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
    if (p->radius > 0) {
        box.lower = ga2d_vec_sub(box.lower, ga2d_vec_make(p->radius, p->radius));
        box.upper = ga2d_vec_add(box.upper, ga2d_vec_make(p->radius, p->radius));
    }
    return box;
}

/* ----------------------------------------------------------- mass (exact) */
/* What a radius r adds to a polygon (Minkowski sum with a disc), as area
   a, first moment mo and second moment j about the point ref:
   - edge i's strip, a rectangle L_i x r standing on the edge: its centre
     the edge's midpoint plus n_i r/2, and I = m (L_i^2 + r^2)/12 about it;
   - vertex i's sector of the disc, between the normals of its two edges,
     of angle alpha (the turn of the rotor n_(i-1) n_i, so the angles make
     a full turn): area alpha r^2/2, its centroid on the bisector at
     d = 4 r sin(alpha/2) / (3 alpha) from the vertex, I = m r^2/2 about
     the vertex, so j = m (r^2/2 + |v - ref|^2 + 2 d b.(v - ref)) about ref
     (parallel axes through the centroid, expanded so nothing cancels).
   Sum: A + r P + pi r^2, the rounded area. */
static void ga2d__add_rounding(const ga2d_polygon *p, ga2d_vec ref, ga2d_real *a, ga2d_vec *mo, ga2d_real *j)
{
    ga2d_real r = p->radius;
    int i, n = p->count;
    for (i = 0; i < n; ++i) {
        ga2d_vec v0 = p->vertices[i], v1 = p->vertices[i + 1 < n ? i + 1 : 0], ni = p->normals[i];
        ga2d_vec np = p->normals[i > 0 ? i - 1 : n - 1], e = ga2d_vec_sub(v1, v0), dv = ga2d_vec_sub(v0, ref), b;
        ga2d_real len = ga2d_vec_length(e), m = len * r, alpha, ms, d;
        /* the strip */
        ga2d_vec c = ga2d_vec_add(ga2d_vec_scale(ga2d_vec_add(ga2d_vec_sub(v0, ref), ga2d_vec_sub(v1, ref)), GA2D__R(0.5)),
                                  ga2d_vec_scale(ni, r / 2));
        *a += m;
        *mo = ga2d_vec_add(*mo, ga2d_vec_scale(c, m));
        *j += m * ((len * len + r * r) / 12 + ga2d_dot(c, c));
        /* the sector at v0, from np to ni */
        alpha = GA2D__ATAN2(ga2d_wedge(np, ni), ga2d_dot(np, ni));
        ms = alpha * r * r / 2;
        d = alpha > 0 ? 4 * r * GA2D__SIN(alpha / 2) / (3 * alpha) : 0;
        if (ga2d_vec_normalize(ga2d_vec_add(np, ni), &b) == 0) b = ni;
        *a += ms;
        *mo = ga2d_vec_add(*mo, ga2d_vec_scale(ga2d_vec_add(dv, ga2d_vec_scale(b, d)), ms));
        *j += ms * (r * r / 2 + ga2d_dot(dv, dv) + 2 * d * ga2d_dot(b, dv));
    }
}

/* Fan the polygon into triangles (r, x_i, x_i+1) about the interior point r
   (the vertex mean).  With d_i = x_i - r and c_i = d_i ^ d_i+1 (twice the
   triangle's signed area):
     A   = 1/2 sum c_i                                   (paper eq. 25)
     C-r = sum c_i (d_i + d_i+1) / (6 A)                 (eq. 24: moments of
                                                          the triangles)
     J_r = sum c_i (d_i.d_i + d_i.d_i+1 + d_i+1.d_i+1) / 12   (eq. 26 exact)
     I_C = J_r - A |C - r|^2                             (parallel axes)
   Every d_i is small even when the polygon is far from the origin, so no
   term is a large number minus a large number.  A radius adds its strips
   and corner sectors (ga2d__add_rounding) to A, the moment and J_r. */
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
    if (!ga2d__finite(density) || !ga2d__finite(p->radius)) return GA2D_ERR_NOT_FINITE;
    if (density < 0 || p->radius < 0) return GA2D_ERR_INVALID_ARGUMENT;
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
    if (p->radius > 0) {
        /* in the sums' units: area2 is 2 A, moment 3 (2 A)(C - r), j12 12 J_r */
        ga2d_real a = 0, j = 0;
        ga2d_vec mo = ga2d_vec_make(0, 0);
        ga2d__add_rounding(p, ref, &a, &mo, &j);
        area2 += 2 * a;
        moment = ga2d_vec_add(moment, ga2d_vec_scale(mo, 6));
        j12 += 12 * j;
    }
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

/* A disc: m = rho pi r^2, I = m r^2 / 2 about its centre. */
GA2D_API ga2d_result ga2d_circle_mass_checked(const ga2d_circle *c, ga2d_real density, ga2d_mass *out)
{
    ga2d_mass m;
    if (!c || !out) return GA2D_ERR_INVALID_ARGUMENT;
    if (!ga2d__finite(density) || !ga2d__finite(c->radius) || !ga2d__finite_vec(c->center)) return GA2D_ERR_NOT_FINITE;
    if (density < 0 || c->radius < 0) return GA2D_ERR_INVALID_ARGUMENT;
    m.mass = density * GA2D__PI * c->radius * c->radius;
    m.center = c->center;
    m.inertia = m.mass * c->radius * c->radius / 2;
    if (!ga2d__finite(m.mass) || !ga2d__finite(m.inertia)) return GA2D_ERR_TOO_LARGE;
    *out = m;
    return GA2D_OK;
}

/* A capsule of length L = |c2 - c1| and radius r about its midpoint: the
   rectangle L x 2r, I = m_rect (L^2 + 4 r^2)/12, and two half discs of
   mass m_h = rho pi r^2/2 each, whose centroids stand d0 = 4r/(3 pi)
   beyond the ends: I = m_h r^2/2 about the flat edge's middle, so
   m_h (r^2/2 - d0^2) about the centroid and m_h (r^2/2 - d0^2 + (L/2 +
   d0)^2) = m_h (r^2/2 + L^2/4 + L d0) about the midpoint.  L = 0 gives
   the disc's m r^2/2. */
GA2D_API ga2d_result ga2d_capsule_mass_checked(const ga2d_capsule *c, ga2d_real density, ga2d_mass *out)
{
    ga2d_mass m;
    ga2d_real r, L, m_rect, m_half, d0;
    if (!c || !out) return GA2D_ERR_INVALID_ARGUMENT;
    if (!ga2d__finite(density) || !ga2d__finite(c->radius) || !ga2d__finite_vec(c->center1) || !ga2d__finite_vec(c->center2))
        return GA2D_ERR_NOT_FINITE;
    if (density < 0 || c->radius < 0) return GA2D_ERR_INVALID_ARGUMENT;
    r = c->radius;
    L = ga2d_vec_length(ga2d_vec_sub(c->center2, c->center1));
    m_rect = density * L * 2 * r;
    m_half = density * GA2D__PI * r * r / 2;
    d0 = 4 * r / (3 * GA2D__PI);
    m.mass = m_rect + 2 * m_half;
    m.center = ga2d_vec_add(c->center1, ga2d_vec_scale(ga2d_vec_sub(c->center2, c->center1), GA2D__R(0.5)));
    m.inertia = m_rect * (L * L + 4 * r * r) / 12 + 2 * m_half * (r * r / 2 + L * L / 4 + L * d0);
    if (!ga2d__finite(m.mass) || !ga2d__finite(m.inertia) || !ga2d__finite_vec(m.center)) return GA2D_ERR_TOO_LARGE;
    *out = m;
    return GA2D_OK;
}

/* The unchecked forms: all zero on bad input. */
GA2D_API ga2d_mass ga2d_circle_mass(const ga2d_circle *c, ga2d_real density)
{
    ga2d_mass m;
    memset(&m, 0, sizeof m);
    if (ga2d_circle_mass_checked(c, density, &m) != GA2D_OK) memset(&m, 0, sizeof m);
    return m;
}

GA2D_API ga2d_mass ga2d_capsule_mass(const ga2d_capsule *c, ga2d_real density)
{
    ga2d_mass m;
    memset(&m, 0, sizeof m);
    if (ga2d_capsule_mass_checked(c, density, &m) != GA2D_OK) memset(&m, 0, sizeof m);
    return m;
}

/* ============================================================= broadphase */
/* A dynamic AABB tree: leaves hold the fattened boxes of bodies, each inner
   node the union of its two children.  Insertion descends toward the
   cheapest sibling by the perimeter ("surface area") heuristic, and AVL
   rotations keep it balanced, so a query visits O(log n + k) nodes.  The
   world keeps two: static bodies in one, moving bodies in the other, so a
   static-static pair can never be made.  Each node also keeps the filter
   categories under it (Box2D v3's trees do), so pair finding skips a
   subtree none of whose shapes its mask lets in: a grid of bodies that
   never touch one another finds no candidates at all. */
typedef struct ga2d__node {
    ga2d_aabb box;
    int parent;           /* or the next free node */
    int child1, child2;   /* -1 at a leaf */
    int height;           /* 0 at a leaf, -1 when free */
    int body;             /* a leaf's shape slot */
    uint32_t category;    /* a leaf's shape's category bits; inner: its children's union */
} ga2d__node;

/* A leaf and its box's centre keys (lower + upper on each axis), side by
   side for the rebuild's passes (ga2d__tree_build). */
typedef struct ga2d__leaf_ref {
    ga2d_real key[2];
    int leaf;
} ga2d__leaf_ref;

typedef struct ga2d__tree {
    ga2d__node *nodes;
    int capacity, used, root, free_list, leaves;
    int *units;        /* room for every node */
    int unit_capacity;
    ga2d__leaf_ref *refs; /* room for every node: the rebuild's leaves */
    int ref_capacity;
    int moved;         /* leaves listed in units to go back in (ga2d__refit_proxies) */
    int marked;        /* some node is marked (ga2d__tree_mark) */
} ga2d__tree;

static ga2d_real ga2d__perimeter(ga2d_aabb b) { return 2 * ((b.upper.x - b.lower.x) + (b.upper.y - b.lower.y)); }

/* Room for `more` new leaves (two nodes each), allocated up front so that
   inserting never fails. */
static int ga2d__tree_reserve(const ga2d_allocator *a, ga2d__tree *t, int more)
{
    int free_nodes = t->capacity - t->used, i;
    for (i = t->free_list; i >= 0 && free_nodes < 2 * more; i = t->nodes[i].parent) ++free_nodes;
    if (free_nodes < 2 * more && !ga2d__grow(a, (void **)&t->nodes, &t->capacity, t->used + 2 * more, sizeof *t->nodes))
        return 0;
    return ga2d__grow(a, (void **)&t->units, &t->unit_capacity, t->capacity, sizeof *t->units) &&
           ga2d__grow(a, (void **)&t->refs, &t->ref_capacity, t->capacity, sizeof *t->refs);
}

static int ga2d__tree_alloc_node(ga2d__tree *t)
{
    int i;
    if (t->free_list >= 0) {
        i = t->free_list;
        t->free_list = t->nodes[i].parent;
    } else {
        GA2D_ASSERT(t->used < t->capacity);
        i = t->used++;
    }
    t->nodes[i].parent = t->nodes[i].child1 = t->nodes[i].child2 = -1;
    t->nodes[i].height = 0;
    t->nodes[i].body = -1;
    return i;
}

static void ga2d__tree_free_node(ga2d__tree *t, int i)
{
    t->nodes[i].height = -1;
    t->nodes[i].parent = t->free_list;
    t->free_list = i;
}

/* One AVL rotation at node a if its subtrees' heights differ by more than
   one; returns the node now at a's place. */
static int ga2d__tree_balance(ga2d__tree *t, int ia)
{
    ga2d__node *n = t->nodes, *a = &n[ia];
    int ib, ic, bal;
    if (a->child1 < 0 || a->height < 2) return ia;
    ib = a->child1;
    ic = a->child2;
    bal = n[ic].height - n[ib].height;
    if (bal > 1 || bal < -1) {
        /* promote the taller child (up), its taller child stays under it */
        int iu = bal > 1 ? ic : ib, io = bal > 1 ? ib : ic; /* up, other */
        ga2d__node *u = &n[iu];
        int i1 = u->child1, i2 = u->child2, keep, move;
        u->child1 = ia;
        u->parent = a->parent;
        a->parent = iu;
        if (u->parent >= 0) {
            if (n[u->parent].child1 == ia) n[u->parent].child1 = iu;
            else n[u->parent].child2 = iu;
        } else {
            t->root = iu;
        }
        keep = n[i1].height > n[i2].height ? i1 : i2;
        move = keep == i1 ? i2 : i1;
        u->child2 = keep;
        if (bal > 1) a->child2 = move;
        else a->child1 = move;
        n[move].parent = ia;
        a->box = ga2d_aabb_union(n[io].box, n[move].box);
        a->category = n[io].category | n[move].category;
        a->height = 1 + (n[io].height > n[move].height ? n[io].height : n[move].height);
        u->box = ga2d_aabb_union(a->box, n[keep].box);
        u->category = a->category | n[keep].category;
        u->height = 1 + (a->height > n[keep].height ? a->height : n[keep].height);
        return iu;
    }
    return ia;
}

/* Refits boxes and heights from node i up to the root, rotating as it
   goes; above i it stops at a node that neither turned nor changed (the
   nodes above that see the same children they were fitted to).  Node i
   itself is always refitted: a caller may have set its fields. */
static void ga2d__tree_refit(ga2d__tree *t, int i)
{
    const int first = i;
    while (i >= 0) {
        ga2d__node *n;
        ga2d_aabb box;
        uint32_t category;
        int c1, c2, height, at = i;
        i = ga2d__tree_balance(t, i);
        n = &t->nodes[i];
        c1 = n->child1;
        c2 = n->child2;
        height = 1 + (t->nodes[c1].height > t->nodes[c2].height ? t->nodes[c1].height : t->nodes[c2].height);
        box = ga2d_aabb_union(t->nodes[c1].box, t->nodes[c2].box);
        category = t->nodes[c1].category | t->nodes[c2].category;
        if (at != first && i == at && height == n->height && category == n->category && box.lower.x == n->box.lower.x &&
            box.lower.y == n->box.lower.y && box.upper.x == n->box.upper.x && box.upper.y == n->box.upper.y)
            return;
        n->height = height;
        n->box = box;
        n->category = category;
        i = n->parent;
    }
}

/* Leaves refitted in a step, taken out and put back one by one, would
   rebuild their paths each time: instead each new leaf box marks its
   ancestors up to the root (ga2d__tree_mark), one pass then refits the
   marked boxes from below (ga2d__tree_tighten; when many moved, every
   box), and only the leaves that
   left their parent's box go back in by the heuristic.  Until the
   tightening a marked box may not hold its children: nothing reads the
   tree in between.  A marked inner node's body, -1 otherwise, is
   GA2D__MARKED. */
#define GA2D__MARKED (-2)
static void ga2d__tree_mark(ga2d__tree *t, int leaf)
{
    ga2d__node *n = t->nodes;
    int i;
    for (i = n[leaf].parent; i >= 0 && n[i].body != GA2D__MARKED; i = n[i].parent) n[i].body = GA2D__MARKED;
    t->marked = 1;
}

/* Whether a leaf's new box has left its sibling (the box holding both is
   larger, by perimeter, than the two apart): then the place the heuristic
   chose for it no longer suits it.  A leaf that keeps near its sibling
   keeps its place, as a net or a crowd moving as one does. */
#ifndef GA2D__STRAY_LEVELS
#define GA2D__STRAY_LEVELS 64
#endif
static int ga2d__tree_strayed(const ga2d__tree *t, int leaf)
{
    const ga2d__node *n = t->nodes;
    int i, parent, sibling, d;
    for (i = leaf, d = 0; (parent = n[i].parent) >= 0 && d < GA2D__STRAY_LEVELS; i = parent, ++d) {
        sibling = n[parent].child1 == i ? n[parent].child2 : n[parent].child1;
        if (ga2d__perimeter(n[parent].box) > ga2d__perimeter(n[i].box) + ga2d__perimeter(n[sibling].box)) return 1;
    }
    return 0;
}

/* The marked boxes (`all`: every inner box), each the union of its
   children's again, from below; the marks cleared.  The stack holds at
   most the height + 1 (see ga2d__tree_query), each node twice (once
   down, once up: a tagged index).  When many leaves moved, one walk over
   every inner box is cheaper than marking their paths (a walk up from
   each leaf, node after dependent node, to the first marked one: half of
   the book-keeping's time in a swinging 100 x 100 grid); a box off every
   moved leaf's path already holds its children exactly (every change
   refits its ancestors), so it gets the bits it has. */
static int ga2d__tree_descends(const ga2d__node *n, int i, int all)
{
    return n[i].height > 0 && (all || n[i].body == GA2D__MARKED);
}
static void ga2d__tree_tighten(ga2d__tree *t, int all)
{
    ga2d__node *n = t->nodes;
    int stack[512], top = 0;
    t->marked = 0;
    if (t->root < 0 || !ga2d__tree_descends(n, t->root, all)) return;
    stack[top++] = t->root;
    while (top > 0) {
        int i = stack[--top];
        if (i < 0) { /* back up: its children are tight */
            i = ~i;
            n[i].box = ga2d_aabb_union(n[n[i].child1].box, n[n[i].child2].box);
            n[i].body = -1;
            continue;
        }
        GA2D_ASSERT(top + 3 <= 512);
        stack[top++] = ~i;
        if (ga2d__tree_descends(n, n[i].child1, all)) stack[top++] = n[i].child1;
        if (ga2d__tree_descends(n, n[i].child2, all)) stack[top++] = n[i].child2;
    }
}

static void ga2d__tree_insert_leaf(ga2d__tree *t, int leaf)
{
    ga2d__node *n = t->nodes;
    ga2d_aabb box = n[leaf].box;
    int s, old_parent, parent;
    ++t->leaves;
    if (t->root < 0) {
        t->root = leaf;
        n[leaf].parent = -1;
        return;
    }
    /* descend: stop where pairing with this node costs less than going
       into either child (perimeter of the new parent plus the growth of
       every box above it) */
    s = t->root;
    while (n[s].child1 >= 0) {
        int c1 = n[s].child1, c2 = n[s].child2;
        ga2d_real area = ga2d__perimeter(n[s].box);
        ga2d_real combined = ga2d__perimeter(ga2d_aabb_union(n[s].box, box));
        ga2d_real cost = 2 * combined, inherit = 2 * (combined - area), cost1, cost2;
        cost1 = ga2d__perimeter(ga2d_aabb_union(box, n[c1].box)) + inherit;
        if (n[c1].child1 >= 0) cost1 -= ga2d__perimeter(n[c1].box);
        cost2 = ga2d__perimeter(ga2d_aabb_union(box, n[c2].box)) + inherit;
        if (n[c2].child1 >= 0) cost2 -= ga2d__perimeter(n[c2].box);
        if (cost < cost1 && cost < cost2) break;
        s = cost1 < cost2 ? c1 : c2;
    }
    old_parent = n[s].parent;
    parent = ga2d__tree_alloc_node(t);
    n = t->nodes;
    n[parent].parent = old_parent;
    n[parent].box = ga2d_aabb_union(box, n[s].box);
    n[parent].category = n[leaf].category | n[s].category;
    n[parent].height = n[s].height + 1;
    n[parent].child1 = s;
    n[parent].child2 = leaf;
    n[s].parent = parent;
    n[leaf].parent = parent;
    if (old_parent >= 0) {
        if (n[old_parent].child1 == s) n[old_parent].child1 = parent;
        else n[old_parent].child2 = parent;
    } else {
        t->root = parent;
    }
    ga2d__tree_refit(t, parent);
}

static void ga2d__tree_remove_leaf(ga2d__tree *t, int leaf)
{
    ga2d__node *n = t->nodes;
    int parent, grand, sibling;
    --t->leaves;
    if (leaf == t->root) {
        t->root = -1;
        return;
    }
    parent = n[leaf].parent;
    grand = n[parent].parent;
    sibling = n[parent].child1 == leaf ? n[parent].child2 : n[parent].child1;
    if (grand >= 0) {
        if (n[grand].child1 == parent) n[grand].child1 = sibling;
        else n[grand].child2 = sibling;
        n[sibling].parent = grand;
        ga2d__tree_free_node(t, parent);
        ga2d__tree_refit(t, grand);
    } else {
        t->root = sibling;
        n[sibling].parent = -1;
        ga2d__tree_free_node(t, parent);
    }
}

/* A new leaf for shape `body` with box `box` and the shape's category
   bits; capacity must have been reserved. */
static int ga2d__tree_create(ga2d__tree *t, ga2d_aabb box, int body, uint32_t category)
{
    int leaf = ga2d__tree_alloc_node(t);
    t->nodes[leaf].box = box;
    t->nodes[leaf].body = body;
    t->nodes[leaf].category = category;
    ga2d__tree_insert_leaf(t, leaf);
    return leaf;
}

static void ga2d__tree_destroy(ga2d__tree *t, int leaf)
{
    ga2d__tree_remove_leaf(t, leaf);
    ga2d__tree_free_node(t, leaf);
}

static void ga2d__tree_move(ga2d__tree *t, int leaf, ga2d_aabb box)
{
    ga2d__tree_remove_leaf(t, leaf);
    t->nodes[leaf].box = box;
    ga2d__tree_insert_leaf(t, leaf);
}

/* The tree built again from its leaves, top down: each node's leaves
   split at the median of their centres along the longer side of the
   centres' box.  When most leaves moved, cheaper than putting them back
   one by one (spinner: 5 250 of 6 076 shapes leave their boxes each step,
   and re-inserted one by one they left a tree whose pair queries took
   17 % of the step, 10 % on the rebuilt one), and the tree is as good as
   new.  Leaves keep their nodes (the shapes hold them); the inner ones
   are taken again lowest index first.  Which pairs a query finds does not
   depend on the tree's shape, and new pairs are sorted before they are
   made: the same bits either way. */
/* Partition refs[0, count) so that the k-th by key is at k, the smaller
   before it (Hoare's selection; the middle item as the pivot).  The keys
   sit beside their leaves, so its passes read one array in order, not
   the nodes at random (a 10 000-leaf rebuild took 6 ms that way). */
static void ga2d__select(ga2d__leaf_ref *refs, int count, int k, int axis)
{
    int lo = 0, hi = count - 1;
    while (lo < hi) {
        ga2d_real pivot = refs[(lo + hi) / 2].key[axis];
        int i = lo, j = hi;
        while (i <= j) {
            while (refs[i].key[axis] < pivot) ++i;
            while (refs[j].key[axis] > pivot) --j;
            if (i <= j) {
                ga2d__leaf_ref r = refs[i];
                refs[i] = refs[j];
                refs[j] = r;
                ++i;
                --j;
            }
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else return;
    }
}
static int ga2d__tree_build(ga2d__tree *t, ga2d__leaf_ref *refs, int count)
{
    ga2d__node *n;
    int node, half, axis;
    ga2d_real lx, ly, ux, uy;
    int i;
    if (count == 1) return refs[0].leaf;
    lx = ux = refs[0].key[0];
    ly = uy = refs[0].key[1];
    for (i = 1; i < count; ++i) {
        ga2d_real x = refs[i].key[0], y = refs[i].key[1];
        lx = x < lx ? x : lx;
        ux = x > ux ? x : ux;
        ly = y < ly ? y : ly;
        uy = y > uy ? y : uy;
    }
    axis = uy - ly > ux - lx;
    half = count / 2;
    ga2d__select(refs, count, half, axis);
    node = ga2d__tree_alloc_node(t);
    n = t->nodes;
    n[node].child1 = ga2d__tree_build(t, refs, half);
    n[node].child2 = ga2d__tree_build(t, refs + half, count - half);
    n = t->nodes;
    n[n[node].child1].parent = node;
    n[n[node].child2].parent = node;
    n[node].box = ga2d_aabb_union(n[n[node].child1].box, n[n[node].child2].box);
    n[node].category = n[n[node].child1].category | n[n[node].child2].category;
    n[node].height = 1 + (n[n[node].child1].height > n[n[node].child2].height ? n[n[node].child1].height : n[n[node].child2].height);
    n[node].body = -1;
    return node;
}
static void ga2d__tree_rebuild(ga2d__tree *t)
{
    ga2d__node *n = t->nodes;
    int i, count = 0;
    t->marked = 0;
    if (t->root < 0) return;
    t->free_list = -1;
    for (i = t->used - 1; i >= 0; --i) {
        if (n[i].height == 0) {
            ga2d__leaf_ref *r = &t->refs[count++];
            r->key[0] = n[i].box.lower.x + n[i].box.upper.x;
            r->key[1] = n[i].box.lower.y + n[i].box.upper.y;
            r->leaf = i;
        } else {
            ga2d__tree_free_node(t, i); /* inner or already free: taken again lowest first */
        }
    }
    t->root = ga2d__tree_build(t, t->refs, count);
    t->nodes[t->root].parent = -1;
}

/* A leaf's shape changed its categories: the unions above it follow. */
static void ga2d__tree_set_category(ga2d__tree *t, int leaf, uint32_t category)
{
    int i;
    t->nodes[leaf].category = category;
    for (i = t->nodes[leaf].parent; i >= 0; i = t->nodes[i].parent)
        t->nodes[i].category = t->nodes[t->nodes[i].child1].category | t->nodes[t->nodes[i].child2].category;
}

/* Calls fn(ctx, body) for every leaf whose box overlaps q and whose
   categories meet `mask` (subtrees with none are skipped whole; with
   GA2D__ALL_CATEGORIES, every leaf, a shape of no category too), in
   depth-first order, child1 first.  A node's two children are tested
   before either is pushed: their two boxes are read at once rather than
   one pop after the other, and a child that misses is never pushed.
   The stack holds at most height + 1 entries; AVL balance keeps the
   height under 1.45 log2(leaves) + 2, far below 256 for any world that
   fits in memory. */
#define GA2D__ALL_CATEGORIES 0xFFFFFFFFu
typedef void ga2d__query_fn(void *ctx, int body);
static int ga2d__node_meets(const ga2d__node *nd, ga2d_aabb q, uint32_t mask)
{
    return (mask == GA2D__ALL_CATEGORIES || (nd->category & mask) != 0) && ga2d_aabb_overlaps(nd->box, q);
}

static void ga2d__tree_query(const ga2d__tree *t, ga2d_aabb q, uint32_t mask, ga2d__query_fn *fn, void *ctx)
{
    int stack[256], top = 0;
    if (t->root < 0 || !ga2d__node_meets(&t->nodes[t->root], q, mask)) return;
    stack[top++] = t->root;
    while (top > 0) {
        const ga2d__node *nd = &t->nodes[stack[--top]];
        int meets1, meets2;
        if (nd->child1 < 0) {
            fn(ctx, nd->body);
            continue;
        }
        meets1 = ga2d__node_meets(&t->nodes[nd->child1], q, mask);
        meets2 = ga2d__node_meets(&t->nodes[nd->child2], q, mask);
        GA2D_ASSERT(top + 2 <= 256);
        if (meets2) stack[top++] = nd->child2;
        if (meets1) stack[top++] = nd->child1;
    }
}

/* Whether the segment p + t d, t in [0, tmax], meets box b (closed): the
   slab test, each axis narrowing [lo, hi] to where the segment is within
   that axis's bounds.  A leaf's box is fattened past its shape, so the
   rounding of the quotients never culls a shape the segment touches. */
static int ga2d__segment_meets_box(ga2d_aabb b, ga2d_vec p, ga2d_vec d, ga2d_real tmax)
{
    ga2d_real lo = 0, hi = tmax, pa[2], da[2], bl[2], bu[2];
    int k;
    pa[0] = p.x, pa[1] = p.y, da[0] = d.x, da[1] = d.y;
    bl[0] = b.lower.x, bl[1] = b.lower.y, bu[0] = b.upper.x, bu[1] = b.upper.y;
    for (k = 0; k < 2; ++k) {
        if (da[k] == 0) {
            if (pa[k] < bl[k] || pa[k] > bu[k]) return 0;
        } else {
            ga2d_real t1 = (bl[k] - pa[k]) / da[k], t2 = (bu[k] - pa[k]) / da[k];
            if (t1 > t2) {
                ga2d_real s = t1;
                t1 = t2;
                t2 = s;
            }
            if (t1 > lo) lo = t1;
            if (t2 < hi) hi = t2;
            if (lo > hi) return 0;
        }
    }
    return 1;
}

/* The leaves whose boxes the segment p + t d, t in [0, *tmax], meets, in
   the tree's order; fn may clip *tmax (later boxes are tested against the
   shorter segment) or return 0 to stop.  Returns 0 when stopped. */
typedef int ga2d__ray_leaf_fn(void *ctx, int leaf_body, ga2d_real *tmax);
static int ga2d__tree_ray(const ga2d__tree *t, ga2d_vec p, ga2d_vec d, ga2d_real *tmax, ga2d__ray_leaf_fn *fn, void *ctx,
                          int *nodes)
{
    int stack[256], top = 0;
    if (t->root < 0) return 1;
    stack[top++] = t->root;
    while (top > 0) {
        const ga2d__node *nd = &t->nodes[stack[--top]];
        ++*nodes;
        if (!ga2d__segment_meets_box(nd->box, p, d, *tmax)) continue;
        if (nd->child1 < 0) {
            if (!fn(ctx, nd->body, tmax)) return 0;
        } else {
            GA2D_ASSERT(top + 2 <= 256);
            stack[top++] = nd->child2;
            stack[top++] = nd->child1;
        }
    }
    return 1;
}

/* The leaves whose boxes overlap q, as ga2d__tree_query, for the world's
   queries: fn returns 0 to stop (then this returns 0), and the nodes
   visited are counted. */
typedef int ga2d__leaf_fn(void *ctx, int leaf_body);
static int ga2d__tree_overlap(const ga2d__tree *t, ga2d_aabb q, ga2d__leaf_fn *fn, void *ctx, int *nodes)
{
    int stack[256], top = 0;
    if (t->root < 0) return 1;
    stack[top++] = t->root;
    while (top > 0) {
        const ga2d__node *nd = &t->nodes[stack[--top]];
        ++*nodes;
        if (!ga2d_aabb_overlaps(nd->box, q)) continue;
        if (nd->child1 < 0) {
            if (!fn(ctx, nd->body)) return 0;
        } else {
            GA2D_ASSERT(top + 2 <= 256);
            stack[top++] = nd->child2;
            stack[top++] = nd->child1;
        }
    }
    return 1;
}

static void ga2d__tree_release(const ga2d_allocator *a, ga2d__tree *t)
{
    GA2D__FREE_ARRAY(a, t->nodes, t->capacity);
    GA2D__FREE_ARRAY(a, t->units, t->unit_capacity);
    GA2D__FREE_ARRAY(a, t->refs, t->ref_capacity);
}

/* ============================================================ narrowphase */
GA2D_API int ga2d_aabb_overlaps(ga2d_aabb a, ga2d_aabb b)
{
    return a.lower.x <= b.upper.x && b.lower.x <= a.upper.x && a.lower.y <= b.upper.y && b.lower.y <= a.upper.y;
}

GA2D_API int ga2d_aabb_contains(ga2d_aabb o, ga2d_aabb i)
{
    return o.lower.x <= i.lower.x && o.lower.y <= i.lower.y && i.upper.x <= o.upper.x && i.upper.y <= o.upper.y;
}

GA2D_API ga2d_aabb ga2d_aabb_union(ga2d_aabb a, ga2d_aabb b)
{
    ga2d_aabb c;
    c.lower.x = a.lower.x < b.lower.x ? a.lower.x : b.lower.x;
    c.lower.y = a.lower.y < b.lower.y ? a.lower.y : b.lower.y;
    c.upper.x = a.upper.x > b.upper.x ? a.upper.x : b.upper.x;
    c.upper.y = a.upper.y > b.upper.y ? a.upper.y : b.upper.y;
    return c;
}

/* A shape's core expressed in some frame: a polygon's vertices and
   normals, or a capsule's or segment's two ends with the normals of its
   two sides (edge 0 from v0 to v1, edge 1 back), and the radius around
   it. */
typedef struct ga2d__hull {
    int count;
    ga2d_vec v[GA2D_MAX_POLYGON_VERTICES];
    ga2d_vec n[GA2D_MAX_POLYGON_VERTICES];
    ga2d_real radius;
} ga2d__hull;

/* The separating-axis test over p1's edge normals: the largest, over
   p1's edges, of the smallest distance of a p2 vertex above that edge.
   Positive: separated along that normal. */
static ga2d_real ga2d__max_separation(const ga2d__hull *p1, const ga2d__hull *p2, int *edge)
{
    ga2d_real best = -GA2D__MAX;
    int i, j;
    *edge = 0;
    for (i = 0; i < p1->count; ++i) {
        ga2d_real lo = GA2D__MAX;
        for (j = 0; j < p2->count; ++j) {
            ga2d_real s = ga2d_dot(p1->n[i], ga2d_vec_sub(p2->v[j], p1->v[i]));
            lo = s < lo ? s : lo;
        }
        if (lo > best) {
            best = lo;
            *edge = i;
        }
    }
    return best;
}

/* The nearest an edge of polygon pe comes to a vertex of polygon pv (both
   in one frame): the distance, the edge, the vertex, the point on the
   edge, and whether that point is one of the edge's ends (then `end` is
   that vertex of pe, else -1). */
typedef struct ga2d__closest {
    ga2d_real dist;
    int edge, vertex, end;
    ga2d_vec on_edge;
} ga2d__closest;

/* |v| as sqrt(x^2 + y^2) where that neither overflows nor loses bits to
   underflow (within one rounding of the scaled ga2d_vec_length, at a
   fraction of its cost); the scaled one elsewhere. */
static ga2d_real ga2d__length(ga2d_vec v)
{
    ga2d_real l2 = v.x * v.x + v.y * v.y;
    if (l2 > GA2D__R(1e-30) && l2 < GA2D__R(1e30)) return GA2D__SQRT(l2);
    return ga2d_vec_length(v);
}

static ga2d__closest ga2d__closest_to_edges(const ga2d__hull *pv, const ga2d__hull *pe, ga2d_real tie)
{
    ga2d__closest c;
    ga2d_real facing = -2;
    int i, j;
    c.dist = GA2D__MAX;
    c.edge = c.vertex = 0;
    c.end = -1;
    c.on_edge = pe->v[0];
    for (j = 0; j < pe->count; ++j) {
        int j2 = j + 1 < pe->count ? j + 1 : 0;
        ga2d_vec e = ga2d_vec_sub(pe->v[j2], pe->v[j]);
        ga2d_real ee = ga2d_dot(e, e);
        for (i = 0; i < pv->count; ++i) {
            ga2d_real t = ga2d_dot(ga2d_vec_sub(pv->v[i], pe->v[j]), e), d;
            int end = -1;
            ga2d_vec q;
            /* no nearer than the edge's line: a pair farther than that
               from the best so far can neither win nor tie */
            if (GA2D__FABS(ga2d_dot(pe->n[j], ga2d_vec_sub(pv->v[i], pe->v[j]))) > c.dist + tie) continue;
            if (t <= 0) { t = 0; end = j; } /* ee > 0: the sign is t/ee's */
            else if ((t /= ee) >= 1) { t = 1; end = j2; }
            q = ga2d_vec_add(pe->v[j], ga2d_vec_scale(e, t));
            d = ga2d__length(ga2d_vec_sub(pv->v[i], q));
            /* nearer by more than `tie` wins; within it, the edge that
               faces the vertex best (a corner is as near to both of its
               edges, and only one of them faces the gap) */
            if (d < c.dist - tie || (d <= c.dist + tie && ga2d_dot(pe->n[j], ga2d_vec_sub(pv->v[i], q)) > facing * d)) {
                facing = d > 0 ? ga2d_dot(pe->n[j], ga2d_vec_sub(pv->v[i], q)) / d : 1;
                c.dist = d;
                c.edge = j;
                c.vertex = i;
                c.end = end;
                c.on_edge = q;
            }
        }
    }
    return c;
}

/* How far the other polygon lies above face i's line (its SAT gap):
   negative when some vertex of it is below, even past the face's ends. */
static ga2d_real ga2d__face_gap(const ga2d__hull *p, int i, const ga2d__hull *other)
{
    ga2d_real lo = GA2D__MAX;
    int j;
    for (j = 0; j < other->count; ++j) {
        ga2d_real g = ga2d_dot(p->n[i], ga2d_vec_sub(other->v[j], p->v[i]));
        lo = g < lo ? g : lo;
    }
    return lo;
}

/* The incident edge: the one whose normal m is most against n, measured
   as |m + n|^2 = 2 sin(angle/2)^2 from -n.  The dot n.m = -cos(angle)
   says the same in exact arithmetic, but rounds to -1 for every edge
   within sqrt(eps) of -n (3e-4 rad in float): the edges of a thin, gently
   curved polygon all tie there, and the first in index order, not the
   lowest, was taken.  m + n keeps the small angle to full precision. */
static int ga2d__incident_edge(const ga2d__hull *inc, ga2d_vec n)
{
    ga2d_real lo = GA2D__MAX;
    int j, best = 0;
    for (j = 0; j < inc->count; ++j) {
        ga2d_vec m = ga2d_vec_add(n, inc->n[j]);
        ga2d_real d = ga2d_dot(m, m);
        if (d < lo) {
            lo = d;
            best = j;
        }
    }
    return best;
}

#define GA2D__FEATURE_FLIP ((uint32_t)1 << 16) /* the reference face is B's */
static uint32_t ga2d__feature_id(int flip, int ia, int ib)
{
    return (flip ? GA2D__FEATURE_FLIP : 0) | ((uint32_t)ia << 8) | (uint32_t)ib;
}

/* Sets point k of m from a point in A's frame (pa: on the reference side,
   as A's frame sees it) with its separation and id. */
static void ga2d__put_point(ga2d_manifold *m, ga2d_transform xa, ga2d_vec d_ab, ga2d_vec local, ga2d_real sep, uint32_t id)
{
    ga2d_manifold_point *mp = &m->points[m->count++];
    memset(mp, 0, sizeof *mp);
    mp->anchor_a = ga2d_rotate(xa.q, local);
    mp->anchor_b = ga2d_vec_sub(mp->anchor_a, d_ab);
    mp->point = ga2d_vec_add(xa.p, mp->anchor_a);
    mp->separation = sep;
    mp->id = id;
}

/* A two-point hull's faces do not bound it along its own line: the
   separation along that line's two directions (how far the other hull
   lies past either end), or -MAX for a polygon.  Collinear capsules end
   to end are apart along it and along no face normal. */
static ga2d_real ga2d__end_separation(const ga2d__hull *p1, const ga2d__hull *p2)
{
    ga2d_vec e = ga2d_vec_make(-p1->n[0].y, p1->n[0].x); /* v0 -> v1 */
    ga2d_real lo = GA2D__MAX, hi = -GA2D__MAX, a0, a1, t;
    int j;
    if (p1->count != 2) return -GA2D__MAX;
    a0 = ga2d_dot(e, p1->v[0]);
    a1 = ga2d_dot(e, p1->v[1]);
    for (j = 0; j < p2->count; ++j) {
        t = ga2d_dot(e, p2->v[j]);
        lo = t < lo ? t : lo;
        hi = t > hi ? t : hi;
    }
    return lo - a1 > a0 - hi ? lo - a1 : a0 - hi;
}

/* The points of reference face i11 of ref (its outward normal n) against
   the incident edge of inc (the edge most against n), in A's frame (flip:
   the reference is B's): the incident edge is clipped to the face's side
   planes, pushed out by ext_lo before the face's start and ext_hi past
   its end (0 for a face that ends at its vertices; a chain's face reaches
   over a valley's neighbour, ga2d__collide_chain), and each end within
   the margin becomes a point. */
static int ga2d__clip_face(const ga2d__hull *ref, int i11, const ga2d__hull *inc, int flip, ga2d_real ext_lo,
                           ga2d_real ext_hi, ga2d_transform xa, ga2d_vec d_ab, ga2d_real slop, ga2d_real margin,
                           ga2d_manifold *m)
{
    int i12 = i11 + 1 < ref->count ? i11 + 1 : 0, i21, i22;
    ga2d_vec n = ref->n[i11], r1 = ref->v[i11], r2 = ref->v[i12], t, v21, v22;
    ga2d_real rsum = ref->radius + inc->radius;
    i21 = ga2d__incident_edge(inc, n);
    i22 = i21 + 1 < inc->count ? i21 + 1 : 0;
    v21 = inc->v[i21];
    v22 = inc->v[i22];
    /* clip the incident edge (v21 -> v22 runs against r1 -> r2) to the
       reference face's extent [0, |r2 - r1|] along its tangent t, pushed
       out by the extensions */
    t = ga2d_vec_perp(n); /* n turned +90 degrees: the edge direction */
    {
        ga2d_real lower1 = 0 - ext_lo, upper1 = ga2d_dot(ga2d_vec_sub(r2, r1), t) + ext_hi;
        ga2d_real upper2 = ga2d_dot(ga2d_vec_sub(v21, r1), t), lower2 = ga2d_dot(ga2d_vec_sub(v22, r1), t);
        ga2d_real span = upper2 - lower2, s_lo, s_hi, lift = inc->radius - ref->radius;
        int keep_lo, keep_hi;
        ga2d_vec v_lo = v22, v_hi = v21;
        /* fractions clamped to the edge: an incident edge lying wholly past
           a side plane is not extended beyond its own ends */
        if (span > 0) {
            ga2d_real f_lo = (lower1 - lower2) / span, f_hi = (upper1 - lower2) / span, tol = GA2D__R(0.1) * slop;
            ga2d_vec e = ga2d_vec_sub(v21, v22);
            f_lo = f_lo < 0 ? 0 : (f_lo > 1 ? 1 : f_lo);
            f_hi = f_hi < 0 ? 0 : (f_hi > 1 ? 1 : f_hi);
            /* an end past a side plane by no more than tol stays where it
               is when the edge is steeper than the face (it rises more
               than it runs): clipped, a rounding's overhang would move it
               up most of the edge (a segment standing on another's end
               lost its contact in one argument order) */
            if (lower2 < lower1 && !(lower1 - lower2 <= tol && GA2D__FABS(ga2d_dot(e, n)) > span))
                v_lo = ga2d_vec_add(v22, ga2d_vec_scale(e, f_lo));
            if (upper2 > upper1 && !(upper2 - upper1 <= tol && GA2D__FABS(ga2d_dot(e, n)) > span))
                v_hi = ga2d_vec_add(v22, ga2d_vec_scale(e, f_hi));
        }
        s_lo = ga2d_dot(ga2d_vec_sub(v_lo, r1), n);
        s_hi = ga2d_dot(ga2d_vec_sub(v_hi, r1), n);
        m->normal = ga2d_rotate(xa.q, flip ? ga2d_vec_neg(n) : n);
        /* the low end lies by r1 and came from v22; the high end by r2 and
           v21.  A core end at height s above the reference line has its
           surface at s - r_inc, the reference surface is at r_ref: the
           point midway stands (s + r_inc - r_ref)/2 below the end */
        keep_lo = s_lo - rsum <= margin;
        keep_hi = s_hi - rsum <= margin;
        /* Two ends within 0.1 slop of each other along the face are one
           point (the deeper): their normal rows differ only by that lever,
           so the solver's 2 x 2 block is singular to rounding (float: a
           capsule's two points 0.1 mm apart gave 1 - p1 p2 = 4e-7), and
           the point it loaded, and the friction each point may hold,
           flipped with rounding from pass to pass: a pile kicked a body
           every hundred steps.  Ends apart along n alone have equal rows
           too: the deeper one is the block's answer then. */
        if (keep_lo && keep_hi && GA2D__FABS(ga2d_dot(ga2d_vec_sub(v_hi, v_lo), t)) <= GA2D__R(0.1) * slop) {
            keep_lo = s_lo <= s_hi;
            keep_hi = !keep_lo;
        }
        if (keep_lo)
            ga2d__put_point(m, xa, d_ab, ga2d_vec_sub(v_lo, ga2d_vec_scale(n, (lift != 0 ? s_lo + lift : s_lo) / 2)),
                            s_lo - rsum, flip ? ga2d__feature_id(1, i22, i11) : ga2d__feature_id(0, i11, i22));
        if (keep_hi)
            ga2d__put_point(m, xa, d_ab, ga2d_vec_sub(v_hi, ga2d_vec_scale(n, (lift != 0 ? s_hi + lift : s_hi) / 2)),
                            s_hi - rsum, flip ? ga2d__feature_id(1, i21, i12) : ga2d__feature_id(0, i12, i21));
    }
    return m->count;
}

/* The manifold of two hulls in A's frame (B's brought into it by
   xa^-1 xb, which subtracts the two positions once, exactly when they are
   close, so nothing below depends on the distance from the origin).
   Steps: SAT over both sets of normals, on the cores; B's face becomes
   the reference only when its separation beats A's by 0.1 slop (so the
   choice does not flicker between nearly equal axes); the incident edge
   is the other hull's edge most against the reference normal.  When the
   cores are apart by more than 0.1 slop the closest features are found
   exactly instead: two vertices give one point at the true distance and
   direction (rounded corners meet there), a vertex facing an edge makes
   that edge the reference (A's again, unless B's is nearer by 0.1 slop).
   The incident edge is clipped to the reference face's side planes and
   each end within the margin becomes a point.  Separations are the
   cores' less both radii, and each point lies midway between the two
   surfaces. */
static int ga2d__collide_hulls(const ga2d__hull *hA, const ga2d__hull *hB, ga2d_transform xa, ga2d_vec d_ab,
                               ga2d_real slop, ga2d_real margin, ga2d_manifold *m)
{
    const ga2d__hull *ref, *inc;
    ga2d_real sep_a, sep_b, sep, rsum = hA->radius + hB->radius;
    int edge_a, edge_b, flip, i11, apart;

    sep_a = ga2d__max_separation(hA, hB, &edge_a);
    m->normal = ga2d_rotate(xa.q, hA->n[edge_a]);
    if (sep_a - rsum > margin) return 0; /* apart along one of A's normals: B's need not be tried */
    sep_b = ga2d__max_separation(hB, hA, &edge_b);
    if (sep_b - rsum > margin) return 0;

    {
        /* a two-point hull apart along its own line: as far apart as that */
        ga2d_real ends = ga2d__end_separation(hA, hB), ends_b = ga2d__end_separation(hB, hA);
        ends = ends > ends_b ? ends : ends_b;
        if (ends - rsum > margin) return 0;
        apart = ends > GA2D__R(0.1) * slop;
    }
    flip = sep_b > sep_a + GA2D__R(0.1) * slop;
    ref = flip ? hB : hA;
    inc = flip ? hA : hB;
    i11 = flip ? edge_b : edge_a;
    sep = flip ? sep_b : sep_a;

    if (apart || sep > GA2D__R(0.1) * slop) {
        /* Apart: the closest features are found exactly, as the nearest
           approach of B's vertices to A's edges (ca) and of A's vertices
           to B's edges (cb); the distance is the smaller.  A face whose
           approach is within 0.1 slop of the distance and which faces the
           gap can be the reference: the SAT's choice above if it does (a
           box landing flat keeps one reference), else the other.  If
           neither face does, two vertices meet: one point at the true
           distance along the true direction. */
        ga2d__closest ca = ga2d__closest_to_edges(hB, hA, GA2D__R(0.1) * slop);
        ga2d__closest cb = ga2d__closest_to_edges(hA, hB, GA2D__R(0.1) * slop);
        const ga2d__closest *c;
        ga2d_real dist = ca.dist < cb.dist ? ca.dist : cb.dist, tol = GA2D__R(0.1) * slop;
        /* a side is a face contact when it comes within tol of the
           distance, its edge faces the gap (the vertex overhangs the
           edge's end by <= tol), and no vertex of the other lies below
           the face's line (its gap is the distance, within tol) */
        int face_a = ca.dist <= dist + tol &&
                     GA2D__FABS(ga2d_wedge(hA->n[ca.edge], ga2d_vec_sub(hB->v[ca.vertex], ca.on_edge))) <= tol &&
                     ga2d__face_gap(hA, ca.edge, hB) >= dist - tol;
        int face_b = cb.dist <= dist + tol &&
                     GA2D__FABS(ga2d_wedge(hB->n[cb.edge], ga2d_vec_sub(hA->v[cb.vertex], cb.on_edge))) <= tol &&
                     ga2d__face_gap(hB, cb.edge, hA) >= dist - tol;
        if (dist - rsum > margin) return 0;
        if (!face_a && !face_b) {
            /* two vertices meet: one point, the true distance and direction */
            ga2d_vec u, qa, qb, mid;
            int ia, ib;
            if (ca.dist <= cb.dist) {
                qa = ca.on_edge; qb = hB->v[ca.vertex]; ia = ca.end; ib = ca.vertex;
            } else {
                qa = hA->v[cb.vertex]; qb = cb.on_edge; ia = cb.vertex; ib = cb.end;
            }
            /* vertices that coincide (a distance that was all rounding, as
               when one polygon is 1e8 times the other's size) have no
               direction: the SAT's axis, from A to B, stands in */
            if (ga2d_vec_normalize(ga2d_vec_sub(qb, qa), &u) == 0) u = flip ? ga2d_vec_neg(hB->n[edge_b]) : hA->n[edge_a];
            m->normal = ga2d_rotate(xa.q, u);
            /* midway between the surfaces, qa + u r_A and qb - u r_B */
            mid = ga2d_vec_scale(ga2d_vec_add(qa, qb), GA2D__R(0.5));
            if (hA->radius != hB->radius) mid = ga2d_vec_add(mid, ga2d_vec_scale(u, (hA->radius - hB->radius) / 2));
            /* no face is the reference: the flip bit is 0 (both searches
               find the same two vertices at one distance, so which of
               them reports it is rounding, and must not show in the id) */
            ga2d__put_point(m, xa, d_ab, mid, dist - rsum, ga2d__feature_id(0, ia < 0 ? 0 : ia, ib < 0 ? 0 : ib));
            return 1;
        }
        /* the SAT's choice (with its hysteresis, above) when that face
           faces the gap, so both argument orders agree; else the other */
        if (flip ? !face_b : !face_a) flip = !flip;
        c = flip ? &cb : &ca;
        ref = flip ? hB : hA;
        inc = flip ? hA : hB;
        i11 = c->edge;
    }

    return ga2d__clip_face(ref, i11, inc, flip, 0, 0, xa, d_ab, slop, margin, m);
}

/* A polygon's hull, placed by x (the identity: A's own frame). */
static void ga2d__polygon_hull(const ga2d_polygon *p, ga2d_transform x, int identity, ga2d__hull *h)
{
    int j;
    h->count = p->count;
    h->radius = p->radius;
    for (j = 0; j < p->count; ++j) {
        h->v[j] = identity ? p->vertices[j] : ga2d_transform_apply(x, p->vertices[j]);
        h->n[j] = identity ? p->normals[j] : ga2d_rotate(x.q, p->normals[j]);
    }
}

/* A capsule's or segment's hull from its two ends (already placed): edge
   0 runs p1 -> p2 with the outward normal on its right, edge 1 back.
   Returns 0 for ends that coincide (no direction: a circle). */
static int ga2d__segment_hull(ga2d_vec p1, ga2d_vec p2, ga2d_real radius, ga2d__hull *h)
{
    ga2d_vec e;
    if (ga2d_vec_normalize(ga2d_vec_sub(p2, p1), &e) == 0) return 0;
    h->count = 2;
    h->radius = radius;
    h->v[0] = p1;
    h->v[1] = p2;
    h->n[0] = ga2d_vec_make(e.y, -e.x);
    h->n[1] = ga2d_vec_make(-e.y, e.x);
    return 1;
}

/* The polygon pair, as the world collides its bodies. */
static int ga2d__collide(const ga2d_polygon *pa, ga2d_transform xa, const ga2d_polygon *pb, ga2d_transform xb,
                         ga2d_real slop, ga2d_real margin, ga2d_manifold *m)
{
    ga2d__hull A, B;
    /* all of it defined, the points not made included: a contact's
       manifold is saved whole in snapshots, and must not carry stack */
    memset(m, 0, sizeof *m);
    ga2d__polygon_hull(pa, xa, 1, &A);
    ga2d__polygon_hull(pb, ga2d_transform_inv_mul(xa, xb), 0, &B);
    return ga2d__collide_hulls(&A, &B, xa, ga2d_vec_sub(xb.p, xa.p), slop, margin, m);
}

/* A feature id's vertex: a hull's vertex k as 0x80 | k, apart from its
   faces' numbers. */
#define GA2D__VERTEX_FEATURE 0x80

/* Whether a face no longer lies across its normal: c's distance from the
   face's line, along its normal (sep) and by the edge e itself (e ^ d / |e|,
   d from the face's start to c), differ by more than 1e-3 |d|, ten times
   the tolerance a normal's direction has.  A core far smaller than the
   rounding of its placement collapses so (its vertices round together,
   its normals stay): the face would measure c along a direction the edge
   has lost. */
static int ga2d__face_collapsed(ga2d_real sep, ga2d_vec e, ga2d_vec d)
{
    ga2d_real le = ga2d__length(e);
    return GA2D__FABS(sep * le + ga2d_wedge(e, d)) > GA2D__R(1e-3) * le * ga2d__length(d);
}

/* The nearest point q of a hull's core to the point c (both in one
   frame), the unit direction u from q to c (out of the core's face when c
   is inside it, as a polygon's core can hold it), the signed distance d
   along u (negative inside) and the feature: a face's index, or a vertex
   as GA2D__VERTEX_FEATURE | index.  For a convex core the face of largest
   separation holds the nearest point, on it or at one of its ends. */
static ga2d_real ga2d__hull_nearest(const ga2d__hull *h, ga2d_vec c, ga2d_vec *q, ga2d_vec *u, int *feature)
{
    ga2d_real best = -GA2D__MAX, t, upper;
    int i, face = 0, i2;
    ga2d_vec e, d;
    for (i = 0; i < h->count; ++i) {
        ga2d_real sep = ga2d_dot(h->n[i], ga2d_vec_sub(c, h->v[i]));
        if (sep > best) {
            best = sep;
            face = i;
        }
    }
    i2 = face + 1 < h->count ? face + 1 : 0;
    e = ga2d_vec_sub(h->v[i2], h->v[face]);
    d = ga2d_vec_sub(c, h->v[face]);
    /* c's foot along the face, and the face's end, measured along the
       face's normal turned +90 degrees (its edge's direction as the shape
       gives it; the clipper measures a reference face so), not along the
       placed edge e: e carries its ends' rounding (eps of their distance
       from this frame's origin), which turns it by that over |e| and moves
       the foot by that angle times |d|.  Seen from far off (|d| >> |e|)
       the foot is lost: c 1e75 off a box 112 wide, 1.4 degrees off its
       side's normal, has its foot 2.4e73 past the side's end, yet the
       side's placed ends rounded to one x (e straight down) put it on the
       face, whose height along the tilted normal falls short of the
       distance by 1 - cos(1.4 degrees) = 3e-4 of 1e75.  Along the normal's
       tangent the foot is off by the ends' and c's rounding alone */
    t = ga2d_dot(d, ga2d_vec_perp(h->n[face]));
    upper = ga2d_dot(e, ga2d_vec_perp(h->n[face]));
    if ((best > 0 || h->count < 3) && (t <= 0 || t >= upper || ga2d__face_collapsed(best, e, d))) {
        /* past an end of the face (a segment's core has no inside, so its
           ends count on its line too): that vertex is nearest */
        ga2d_vec d2 = ga2d_vec_sub(c, h->v[i2]);
        int k = t <= 0 || (t < upper && ga2d_dot(d, d) <= ga2d_dot(d2, d2)) ? face : i2;
        ga2d_vec r = k == face ? d : d2;
        ga2d_real dist = ga2d__length(r);
        *q = h->v[k];
        *feature = GA2D__VERTEX_FEATURE | k;
        if (dist >= GA2D__MIN_NORMAL) { /* 1/dist overflows below: coincident then */
            *u = ga2d_vec_scale(r, 1 / dist);
            return dist;
        }
        *u = h->n[face];
        return 0;
    }
    *u = h->n[face];
    *q = ga2d_vec_sub(c, ga2d_vec_scale(*u, best));
    *feature = face;
    return best;
}

/* One point between a hull (A, or B when flip) and a circle of centre c
   and radius rc, in A's frame.  The normal runs from A to B. */
static int ga2d__collide_hull_circle(const ga2d__hull *h, ga2d_vec c, ga2d_real rc, int flip, ga2d_transform xa,
                                     ga2d_vec d_ab, ga2d_real margin, ga2d_manifold *m)
{
    ga2d_vec q, u, mid;
    int feature;
    ga2d_real d = ga2d__hull_nearest(h, c, &q, &u, &feature), sep = d - h->radius - rc;
    if (sep > margin) return 0;
    /* midway between the surfaces, q + u r_h and c - u r_c */
    mid = ga2d_vec_add(ga2d_vec_scale(ga2d_vec_add(q, c), GA2D__R(0.5)), ga2d_vec_scale(u, (h->radius - rc) / 2));
    m->normal = ga2d_rotate(xa.q, flip ? ga2d_vec_neg(u) : u);
    ga2d__put_point(m, xa, d_ab, mid, sep, flip ? ga2d__feature_id(1, 0, feature) : ga2d__feature_id(0, feature, 0));
    return 1;
}

/* Two circles, centres ca and cb in A's frame: one point on the line of
   centres (A's x axis when they coincide). */
static int ga2d__collide_circles(ga2d_vec ca, ga2d_real ra, ga2d_vec cb, ga2d_real rb, ga2d_transform xa, ga2d_vec d_ab,
                                 ga2d_real margin, ga2d_manifold *m)
{
    ga2d_vec r = ga2d_vec_sub(cb, ca), u, mid;
    ga2d_real d = ga2d__length(r), sep = d - ra - rb;
    if (sep > margin) return 0;
    u = d >= GA2D__MIN_NORMAL ? ga2d_vec_scale(r, 1 / d) : ga2d_vec_make(1, 0); /* 1/d overflows below */
    mid = ga2d_vec_add(ga2d_vec_scale(ga2d_vec_add(ca, cb), GA2D__R(0.5)), ga2d_vec_scale(u, (ra - rb) / 2));
    m->normal = ga2d_rotate(xa.q, u);
    ga2d__put_point(m, xa, d_ab, mid, sep, ga2d__feature_id(0, 0, 0));
    return 1;
}

/* A segment's or chain segment's segment. */
static const ga2d_segment *ga2d__segment_of(const ga2d_geometry *g)
{
    return g->type == GA2D_SHAPE_CHAIN_SEGMENT ? &g->as.chain_segment.segment : &g->as.segment;
}

/* A shape as its hull in a frame (x applied unless identity), or as a
   circle (returns 0: centre *c, radius *r) when it has no edges. */
static int ga2d__geometry_hull(const ga2d_geometry *g, ga2d_transform x, int identity, ga2d__hull *h, ga2d_vec *c,
                               ga2d_real *r)
{
    ga2d_vec p1, p2;
    ga2d_real radius = 0;
    switch (g->type) {
    case GA2D_SHAPE_POLYGON:
        ga2d__polygon_hull(&g->as.polygon, x, identity, h);
        return 1;
    case GA2D_SHAPE_CIRCLE:
        *c = identity ? g->as.circle.center : ga2d_transform_apply(x, g->as.circle.center);
        *r = g->as.circle.radius;
        return 0;
    case GA2D_SHAPE_CAPSULE:
        p1 = g->as.capsule.center1;
        p2 = g->as.capsule.center2;
        radius = g->as.capsule.radius;
        break;
    default: /* segments */
        p1 = ga2d__segment_of(g)->point1;
        p2 = ga2d__segment_of(g)->point2;
        break;
    }
    if (!identity) {
        p1 = ga2d_transform_apply(x, p1);
        p2 = ga2d_transform_apply(x, p2);
    }
    if (ga2d__segment_hull(p1, p2, radius, h)) return 1;
    *c = p1; /* its ends coincide: a circle */
    *r = radius;
    return 0;
}

/* Below this sine a normal is a chain segment's own face normal: the
   rounding of a unit normal (a vertex normal any larger at a straight or
   valley join is the neighbour's face's to give, and would push sideways). */
#define GA2D__CHAIN_SIN_TOL (16 * GA2D__EPS)

/* The left (front) normal of a unit direction: d e12. */
static ga2d_vec ga2d__left(ga2d_vec d) { return ga2d_vec_make(-d.y, d.x); }

/* A chain segment's joins, in its frame: its direction e1 and front
   normal n1 and, at each end k (0: point1, 1: point2), the neighbour's
   direction e[k] walking the chain, whether the chain turns left there (a
   valley) and how far the neighbour reaches past that end along e1.
   Returns 0 for a segment of no length. */
typedef struct ga2d__chain_joins {
    ga2d_vec e1, n1, e[2];
    int valley[2];
    ga2d_real reach[2];
} ga2d__chain_joins;

static int ga2d__chain_joins_of(const ga2d_chain_segment *cs, ga2d__chain_joins *j)
{
    ga2d_vec back = ga2d_vec_sub(cs->segment.point1, cs->ghost1), ahead = ga2d_vec_sub(cs->ghost2, cs->segment.point2);
    ga2d_real r0, r1;
    if (ga2d_vec_normalize(ga2d_vec_sub(cs->segment.point2, cs->segment.point1), &j->e1) == 0) return 0;
    j->n1 = ga2d__left(j->e1);
    ga2d_vec_normalize(back, &j->e[0]);
    ga2d_vec_normalize(ahead, &j->e[1]);
    j->valley[0] = ga2d_wedge(j->e[0], j->e1) > 0;
    j->valley[1] = ga2d_wedge(j->e1, j->e[1]) > 0;
    r0 = ga2d_dot(back, j->e1);
    r1 = ga2d_dot(ahead, j->e1);
    j->reach[0] = r0 > 0 ? r0 : 0;
    j->reach[1] = r1 > 0 ? r1 : 0;
    return 1;
}

/* What a chain segment does with a contact normal u (its frame, from the
   segment out).  Its own face normal is kept.  Any other normal leans
   over an end, toward the vertex the neighbour shares.  At a valley (the
   chain turns left there) the two faces bound what lies in front of both,
   so the normal snaps to the face's: the face, carried on over the
   neighbour, keeps a body that crosses the join within one step out
   (dropped instead, nothing held it and it went through the other arm).
   At a hilltop (it turns right) the vertex's normals lie between the two
   faces' normals: each segment keeps the half nearer its own and drops
   the rest, as it drops a normal that does not point to its front; a
   straight join has no vertex normals at all.  So a body crossing a join
   meets one face or the other, never an edge that is not there (Catto's
   ghost vertices). */
enum { GA2D__CHAIN_DROP, GA2D__CHAIN_KEEP, GA2D__CHAIN_SNAP };
static int ga2d__chain_normal(const ga2d__chain_joins *j, ga2d_vec u)
{
    int end = ga2d_dot(u, j->e1) < 0 ? 0 : 1;
    ga2d_vec n;
    if (ga2d_dot(u, j->n1) > 0 && GA2D__FABS(ga2d_wedge(j->n1, u)) <= GA2D__CHAIN_SIN_TOL) return GA2D__CHAIN_KEEP;
    if (j->valley[end]) return GA2D__CHAIN_SNAP;
    if (!(ga2d_dot(u, j->n1) > 0)) return GA2D__CHAIN_DROP;
    n = ga2d__left(j->e[end]);
    /* within the vertex's normals (from n1 round to n, not past n: a
       straight join has none but n1's), and in n1's half of them; the
       bisector is the later segment's (its point1 end), so one keeps it */
    if ((end == 0 ? ga2d_wedge(u, n) : ga2d_wedge(n, u)) < 0) return GA2D__CHAIN_DROP;
    if (end == 0) return ga2d_dot(u, j->n1) >= ga2d_dot(u, n) ? GA2D__CHAIN_KEEP : GA2D__CHAIN_DROP;
    return ga2d_dot(u, j->n1) > ga2d_dot(u, n) ? GA2D__CHAIN_KEEP : GA2D__CHAIN_DROP;
}

/* B against a chain segment's face (hull A: face 1 is the front), its
   side planes carried on over a valley's neighbour as far as that reaches
   along the face: the face's line bounds everything in front of the
   neighbour there.  B is a hull (hb) or the circle (cb, rb). */
static int ga2d__chain_face(const ga2d__chain_joins *j, const ga2d__hull *A, int hb, const ga2d__hull *B, ga2d_vec cb,
                            ga2d_real rb, ga2d_transform xa, ga2d_vec d_ab, ga2d_real slop, ga2d_real margin,
                            ga2d_manifold *m)
{
    /* face 1 runs from point2 to point1: before its start lies end 1 */
    ga2d_real past2 = j->valley[1] ? j->reach[1] : 0, past1 = j->valley[0] ? j->reach[0] : 0, d, along;
    ga2d_vec q, mid;
    if (hb) return ga2d__clip_face(A, 1, B, 0, past2, past1, xa, d_ab, slop, margin, m);
    d = ga2d_dot(j->n1, ga2d_vec_sub(cb, A->v[0]));
    along = ga2d_dot(j->e1, ga2d_vec_sub(cb, A->v[0]));
    if (d - rb > margin || along < -past1 || along > ga2d_dot(j->e1, ga2d_vec_sub(A->v[1], A->v[0])) + past2) return 0;
    /* midway between the surfaces, the foot q and cb - n1 rb */
    q = ga2d_vec_sub(cb, ga2d_vec_scale(j->n1, d));
    mid = ga2d_vec_sub(ga2d_vec_scale(ga2d_vec_add(q, cb), GA2D__R(0.5)), ga2d_vec_scale(j->n1, rb / 2));
    m->normal = ga2d_rotate(xa.q, j->n1);
    ga2d__put_point(m, xa, d_ab, mid, d - rb, ga2d__feature_id(0, 1, 0));
    return 1;
}

/* A chain segment (A, placed by xa) against any shape but a chain's (B):
   the segment's manifold, kept when B's centre lies in front of it and
   the normal is one the joins allow, snapped to the face at a valley
   (ga2d__chain_normal).  Near a valley the face is tried even when the
   segment itself is out of reach: B over the neighbour may still be
   within the margin of the face's line. */
static int ga2d__collide_chain(const ga2d_chain_segment *cs, ga2d_transform xa, const ga2d_geometry *gb, ga2d_transform xb,
                               ga2d_real slop, ga2d_real margin, ga2d_manifold *m)
{
    ga2d__hull A, B;
    ga2d__chain_joins j;
    ga2d_vec cb, centre, d_ab = ga2d_vec_sub(xb.p, xa.p);
    ga2d_real rb = 0;
    int hb, n, k;
    memset(m, 0, sizeof *m);
    if (!ga2d__segment_hull(cs->segment.point1, cs->segment.point2, 0, &A) || !ga2d__chain_joins_of(cs, &j)) return 0;
    hb = ga2d__geometry_hull(gb, ga2d_transform_inv_mul(xa, xb), 0, &B, &cb, &rb);
    centre = cb;
    if (hb) {
        centre = ga2d_vec_make(0, 0);
        for (k = 0; k < B.count; ++k) centre = ga2d_vec_add(centre, ga2d_vec_scale(B.v[k], 1 / (ga2d_real)B.count));
    }
    if (ga2d_dot(j.n1, ga2d_vec_sub(centre, cs->segment.point1)) < 0) return 0; /* behind: one-sided */
    n = hb ? ga2d__collide_hulls(&A, &B, xa, d_ab, slop, margin, m) : ga2d__collide_hull_circle(&A, cb, rb, 0, xa, d_ab, margin, m);
    if (n > 0) {
        int kind = ga2d__chain_normal(&j, ga2d_rotate_inv(xa.q, m->normal));
        if (kind == GA2D__CHAIN_KEEP) return n;
        if (kind == GA2D__CHAIN_DROP) {
            memset(m, 0, sizeof *m);
            return 0;
        }
    } else if (!j.valley[0] && !j.valley[1]) {
        return 0;
    }
    memset(m, 0, sizeof *m);
    return ga2d__chain_face(&j, &A, hb, &B, cb, rb, xa, d_ab, slop, margin, m);
}

/* The manifold seen from the other side: B's becomes A's. */
static void ga2d__flip_manifold(ga2d_manifold *m)
{
    int k;
    m->normal = ga2d_vec_neg(m->normal);
    for (k = 0; k < m->count; ++k) {
        ga2d_manifold_point *p = &m->points[k];
        ga2d_vec t = p->anchor_a;
        p->anchor_a = p->anchor_b;
        p->anchor_b = t;
        p->id ^= GA2D__FEATURE_FLIP;
    }
}

/* Any pair of shapes, in A's frame. */
static int ga2d__collide_geometries(const ga2d_geometry *ga, ga2d_transform xa, const ga2d_geometry *gb, ga2d_transform xb,
                                    ga2d_real slop, ga2d_real margin, ga2d_manifold *m)
{
    ga2d__hull A, B;
    ga2d_vec ca, cb, d_ab = ga2d_vec_sub(xb.p, xa.p);
    ga2d_real ra = 0, rb = 0;
    int ha, hb;
    if (ga->type == GA2D_SHAPE_CHAIN_SEGMENT && gb->type == GA2D_SHAPE_CHAIN_SEGMENT) {
        memset(m, 0, sizeof *m);
        return 0;
    }
    if (ga->type == GA2D_SHAPE_CHAIN_SEGMENT) return ga2d__collide_chain(&ga->as.chain_segment, xa, gb, xb, slop, margin, m);
    if (gb->type == GA2D_SHAPE_CHAIN_SEGMENT) {
        int n = ga2d__collide_chain(&gb->as.chain_segment, xb, ga, xa, slop, margin, m);
        ga2d__flip_manifold(m);
        return n;
    }
    memset(m, 0, sizeof *m);
    ha = ga2d__geometry_hull(ga, xa, 1, &A, &ca, &ra);
    hb = ga2d__geometry_hull(gb, ga2d_transform_inv_mul(xa, xb), 0, &B, &cb, &rb);
    if (ha && hb) return ga2d__collide_hulls(&A, &B, xa, d_ab, slop, margin, m);
    if (ha) return ga2d__collide_hull_circle(&A, cb, rb, 0, xa, d_ab, margin, m);
    if (hb) return ga2d__collide_hull_circle(&B, ca, ra, 1, xa, d_ab, margin, m);
    return ga2d__collide_circles(ca, ra, cb, rb, xa, d_ab, margin, m);
}

static int ga2d__polygon_ok(const ga2d_polygon *p) { return p && p->count >= 3 && p->count <= GA2D_MAX_POLYGON_VERTICES; }
static int ga2d__transform_ok(ga2d_transform x)
{
    return ga2d__finite_vec(x.p) && ga2d__finite(x.q.c) && ga2d__finite(x.q.s);
}

/* How far |n|^2 (a normal's, a rotor's) may be from 1: a rotor that far
   off scales what it turns by 5e-5, 50 um on a metre, a hundredth of the
   slop; rotors from ga2d_rotor_from_angle, the world's bodies and short
   products of them are within a few eps. */
#define GA2D__UNIT_TOL 1e-4

static int ga2d__unit_ok(ga2d_real x2) { return GA2D__FABS(x2 - 1) <= GA2D__R(GA2D__UNIT_TOL); }

/* A polygon as ga2d_polygon_make leaves it, checked in O(n) for the
   world-free collider (a hand-filled struct could be anything): finite
   vertices, nonzero edges, and each normal a unit vector pointing out of
   its edge (perpendicular within the unit tolerance).  0 for NOT_FINITE,
   -1 for an inconsistent polygon, 1 when fine. */
static int ga2d__polygon_consistent(const ga2d_polygon *p)
{
    int i;
    for (i = 0; i < p->count; ++i)
        if (!ga2d__finite_vec(p->vertices[i]) || !ga2d__finite_vec(p->normals[i])) return 0;
    for (i = 0; i < p->count; ++i) {
        ga2d_vec e = ga2d_vec_sub(p->vertices[i + 1 < p->count ? i + 1 : 0], p->vertices[i]), n = p->normals[i];
        ga2d_real len = ga2d_vec_length(e);
        if (!(len > 0) || !ga2d__unit_ok(ga2d_dot(n, n))) return -1;
        /* outward: n ^ e > 0 for a CCW edge; perpendicular: |n . e| small */
        if (!(ga2d_wedge(n, e) > 0) || GA2D__FABS(ga2d_dot(n, e)) > GA2D__R(GA2D__UNIT_TOL) * len) return -1;
    }
    return 1;
}

/* A polygon as the world-free collider takes it: 0 or -GA2D_ERR_*. */
static int ga2d__polygon_input(const ga2d_polygon *p)
{
    int c;
    if (!ga2d__polygon_ok(p)) return -(int)GA2D_ERR_INVALID_ARGUMENT;
    c = ga2d__polygon_consistent(p);
    if (c == 0 || !ga2d__finite(p->radius)) return -(int)GA2D_ERR_NOT_FINITE;
    if (c < 0 || p->radius < 0) return -(int)GA2D_ERR_INVALID_ARGUMENT;
    return 0;
}

/* A radius as it may be: finite, not negative. */
static int ga2d__radius_input(ga2d_real r)
{
    if (!ga2d__finite(r)) return -(int)GA2D_ERR_NOT_FINITE;
    return r < 0 ? -(int)GA2D_ERR_INVALID_ARGUMENT : 0;
}

/* Any shape as the world-free collider takes it: 0 or -GA2D_ERR_*. */
static int ga2d__geometry_input(const ga2d_geometry *g)
{
    if (!g) return -(int)GA2D_ERR_INVALID_ARGUMENT;
    switch (g->type) {
    case GA2D_SHAPE_POLYGON: return ga2d__polygon_input(&g->as.polygon);
    case GA2D_SHAPE_CIRCLE:
        if (!ga2d__finite_vec(g->as.circle.center)) return -(int)GA2D_ERR_NOT_FINITE;
        return ga2d__radius_input(g->as.circle.radius);
    case GA2D_SHAPE_CAPSULE:
        if (!ga2d__finite_vec(g->as.capsule.center1) || !ga2d__finite_vec(g->as.capsule.center2))
            return -(int)GA2D_ERR_NOT_FINITE;
        return ga2d__radius_input(g->as.capsule.radius);
    case GA2D_SHAPE_SEGMENT:
        return ga2d__finite_vec(g->as.segment.point1) && ga2d__finite_vec(g->as.segment.point2) ? 0 : -(int)GA2D_ERR_NOT_FINITE;
    case GA2D_SHAPE_CHAIN_SEGMENT: {
        const ga2d_chain_segment *c = &g->as.chain_segment;
        return ga2d__finite_vec(c->ghost1) && ga2d__finite_vec(c->segment.point1) && ga2d__finite_vec(c->segment.point2) &&
                       ga2d__finite_vec(c->ghost2)
                   ? 0
                   : -(int)GA2D_ERR_NOT_FINITE;
    }
    default: return -(int)GA2D_ERR_INVALID_ARGUMENT;
    }
}

/* The transforms and unit as the world-free collider takes them. */
static int ga2d__collide_input(ga2d_transform xa, ga2d_transform xb, ga2d_real units)
{
    if (!ga2d__transform_ok(xa) || !ga2d__transform_ok(xb) || !ga2d__finite(units)) return -(int)GA2D_ERR_NOT_FINITE;
    /* the normal is promised unit: it is turned by these rotors */
    if (!ga2d__unit_ok(xa.q.c * xa.q.c + xa.q.s * xa.q.s) || !ga2d__unit_ok(xb.q.c * xb.q.c + xb.q.s * xb.q.s))
        return -(int)GA2D_ERR_INVALID_ARGUMENT;
    return units > 0 ? 0 : -(int)GA2D_ERR_INVALID_ARGUMENT;
}

GA2D_API int ga2d_collide_polygons_scaled(const ga2d_polygon *a, ga2d_transform xa, const ga2d_polygon *b,
                                          ga2d_transform xb, ga2d_real units, ga2d_manifold *out)
{
    ga2d_manifold m;
    int ca, cb, r;
    if (!out || !ga2d__polygon_ok(a) || !ga2d__polygon_ok(b)) return -(int)GA2D_ERR_INVALID_ARGUMENT;
    if (!ga2d__transform_ok(xa) || !ga2d__transform_ok(xb) || !ga2d__finite(units)) return -(int)GA2D_ERR_NOT_FINITE;
    ca = ga2d__polygon_input(a);
    cb = ga2d__polygon_input(b);
    if (ca == -(int)GA2D_ERR_NOT_FINITE || cb == -(int)GA2D_ERR_NOT_FINITE) return -(int)GA2D_ERR_NOT_FINITE;
    if (ca < 0 || cb < 0) return -(int)GA2D_ERR_INVALID_ARGUMENT;
    if ((r = ga2d__collide_input(xa, xb, units)) < 0) return r;
    ga2d__collide(a, xa, b, xb, GA2D__R(GA2D_LINEAR_SLOP) * units, GA2D__R(GA2D_SPECULATIVE_DISTANCE) * units, &m);
    *out = m;
    return m.count;
}

GA2D_API int ga2d_collide_shapes_scaled(const ga2d_geometry *a, ga2d_transform xa, const ga2d_geometry *b,
                                        ga2d_transform xb, ga2d_real units, ga2d_manifold *out)
{
    ga2d_manifold m;
    int ca, cb, r;
    if (!out || !a || !b) return -(int)GA2D_ERR_INVALID_ARGUMENT;
    if ((r = ga2d__collide_input(xa, xb, units)) == -(int)GA2D_ERR_NOT_FINITE) return r;
    ca = ga2d__geometry_input(a);
    cb = ga2d__geometry_input(b);
    if (ca == -(int)GA2D_ERR_NOT_FINITE || cb == -(int)GA2D_ERR_NOT_FINITE) return -(int)GA2D_ERR_NOT_FINITE;
    if (ca < 0 || cb < 0) return -(int)GA2D_ERR_INVALID_ARGUMENT;
    if (r < 0) return r;
    ga2d__collide_geometries(a, xa, b, xb, GA2D__R(GA2D_LINEAR_SLOP) * units, GA2D__R(GA2D_SPECULATIVE_DISTANCE) * units, &m);
    *out = m;
    return m.count;
}

GA2D_API int ga2d_collide_shapes(const ga2d_geometry *a, ga2d_transform xa, const ga2d_geometry *b, ga2d_transform xb,
                                 ga2d_manifold *out)
{
    return ga2d_collide_shapes_scaled(a, xa, b, xb, 1, out);
}

GA2D_API int ga2d_collide_polygons(const ga2d_polygon *a, ga2d_transform xa, const ga2d_polygon *b,
                                   ga2d_transform xb, ga2d_manifold *out)
{
    return ga2d_collide_polygons_scaled(a, xa, b, xb, 1, out);
}

/* -------------------------------------------------------------- ray casts */
/* A ray p + t u, u unit, t in [0, best->t] (metres along it), against the
   pieces a shape's boundary is made of; each piece that meets it from
   outside sooner than best->t takes best.  A shape is convex, and the ray
   starts outside it: the first piece met is where it enters. */
typedef struct ga2d__ray_hit { ga2d_real t; ga2d_vec normal; int hit; } ga2d__ray_hit;

/* The circle (c, r): with s = p - c, the closest approach to c is at
   tc = -(s . u), offset q = s + tc u (formed so, not from |s|^2 - tc^2,
   which cancels when the ray passes far off); the ray enters at
   tc - sqrt(r^2 - q^2). */
static void ga2d__ray_circle(ga2d_vec c, ga2d_real r, ga2d_vec p, ga2d_vec u, ga2d__ray_hit *best)
{
    ga2d_vec s = ga2d_vec_sub(p, c), q, n;
    ga2d_real tc = -ga2d_dot(s, u), h2, t;
    q = ga2d_vec_add(s, ga2d_vec_scale(u, tc));
    h2 = r * r - ga2d_dot(q, q);
    if (h2 < 0) return;
    t = tc - GA2D__SQRT(h2);
    if (t < 0 || t > best->t) return;
    n = ga2d_vec_add(s, ga2d_vec_scale(u, t));
    if (ga2d_vec_normalize(n, &n) == 0) n = ga2d_vec_neg(u); /* r = 0: a point met head on */
    best->t = t;
    best->normal = n;
    best->hit = 1;
}

/* The flat piece a -> a + e with outward normal n, met from its front. */
static void ga2d__ray_face(ga2d_vec a, ga2d_vec e, ga2d_vec n, ga2d_vec p, ga2d_vec u, ga2d__ray_hit *best)
{
    ga2d_real den = ga2d_dot(n, u), t, along;
    if (!(den < 0)) return; /* leaving it, or along it */
    t = ga2d_dot(n, ga2d_vec_sub(a, p)) / den;
    if (t < 0 || t > best->t) return;
    along = ga2d_dot(ga2d_vec_sub(ga2d_vec_add(p, ga2d_vec_scale(u, t)), a), e);
    if (along < 0 || along > ga2d_dot(e, e)) return;
    best->t = t;
    best->normal = n;
    best->hit = 1;
}

/* A sharp polygon by clipping the ray to each edge's inner half-plane
   (n . (x - v) <= 0): an edge the ray crosses inward raises the entry,
   one it crosses outward lowers the exit.  No edge ever raises the entry
   when the ray starts inside; a ray through a corner keeps entry = exit,
   a hit. */
static void ga2d__ray_sharp(const ga2d__hull *h, ga2d_vec p, ga2d_vec u, ga2d__ray_hit *best)
{
    ga2d_real lower = 0, upper = best->t;
    int i, index = -1;
    for (i = 0; i < h->count; ++i) {
        ga2d_real num = ga2d_dot(h->n[i], ga2d_vec_sub(h->v[i], p)), den = ga2d_dot(h->n[i], u);
        if (den == 0) {
            if (num < 0) return; /* outside this edge, and running along it */
        } else if (den < 0 && num < lower * den) {
            lower = num / den;
            index = i;
        } else if (den > 0 && num < upper * den) {
            upper = num / den;
        }
        if (upper < lower) return;
    }
    if (index < 0) return;
    best->t = lower;
    best->normal = h->n[index];
    best->hit = 1;
}

/* A hull grown by its radius (a rounded polygon, a capsule): its pieces
   are each edge pushed out by the radius and a circle at each vertex.  A
   ray that starts within the radius of the core is inside. */
static void ga2d__ray_round(const ga2d__hull *h, ga2d_vec p, ga2d_vec u, ga2d__ray_hit *best)
{
    ga2d_vec q, dir;
    int i, feature;
    if (ga2d__hull_nearest(h, p, &q, &dir, &feature) <= h->radius) return;
    for (i = 0; i < h->count; ++i) {
        ga2d_vec a = h->v[i], b = h->v[i + 1 < h->count ? i + 1 : 0], off = ga2d_vec_scale(h->n[i], h->radius);
        ga2d__ray_face(ga2d_vec_add(a, off), ga2d_vec_sub(b, a), h->n[i], p, u, best);
        ga2d__ray_circle(a, h->radius, p, u, best);
    }
}

/* A segment a -> a + e: p + t u = a + s e solved by wedging with e and
   with u, t = ((a - p) ^ e) / (u ^ e), s = ((a - p) ^ u) / (u ^ e).
   Parallel (u ^ e = 0): no hit.  One-sided: only from its left, where
   e e12 points. */
static void ga2d__ray_segment(ga2d_vec a, ga2d_vec b, int one_sided, ga2d_vec p, ga2d_vec u, ga2d__ray_hit *best)
{
    ga2d_vec e = ga2d_vec_sub(b, a), ap = ga2d_vec_sub(a, p), n;
    ga2d_real den = ga2d_wedge(u, e), t, s;
    if (den == 0 || ga2d_vec_normalize(ga2d_vec_perp(e), &n) == 0) return;
    if (ga2d_dot(n, u) > 0) {
        if (one_sided) return; /* from behind */
        n = ga2d_vec_neg(n);
    }
    t = ga2d_wedge(ap, e) / den;
    s = ga2d_wedge(ap, u) / den;
    if (t < 0 || t > best->t || s < 0 || s > 1) return;
    best->t = t;
    best->normal = n;
    best->hit = 1;
}

/* A hit's point as computed, or where that rounded past the real range
   (a ray ending within rounding of its end, a turn back from the shape's
   frame there), p + f d: f <= 1, so each coordinate lies between p's and
   p + d's, which the input checks have found finite. */
static ga2d_vec ga2d__ray_point(ga2d_vec computed, ga2d_vec p, ga2d_vec d, ga2d_real f)
{
    return ga2d__finite_vec(computed) ? computed : ga2d_vec_add(p, ga2d_vec_scale(d, f));
}

/* The ray p + t d, t in [0, 1], against g in its own frame. */
static ga2d_ray_result ga2d__ray_geometry(const ga2d_geometry *g, ga2d_vec p, ga2d_vec d)
{
    ga2d_ray_result out;
    ga2d__ray_hit best;
    ga2d__hull h;
    ga2d_vec u;
    ga2d_real len = ga2d_vec_normalize(d, &u);
    memset(&out, 0, sizeof out);
    if (!(len > 0) || !ga2d__finite(len)) return out;
    best.t = len;
    best.hit = 0;
    best.normal = ga2d_vec_make(0, 0);
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE:
        if (ga2d_vec_length_sq(ga2d_vec_sub(p, g->as.circle.center)) > g->as.circle.radius * g->as.circle.radius)
            ga2d__ray_circle(g->as.circle.center, g->as.circle.radius, p, u, &best);
        break;
    case GA2D_SHAPE_CAPSULE:
        if (ga2d__segment_hull(g->as.capsule.center1, g->as.capsule.center2, g->as.capsule.radius, &h)) {
            ga2d__ray_round(&h, p, u, &best);
        } else if (ga2d_vec_length_sq(ga2d_vec_sub(p, g->as.capsule.center1)) > g->as.capsule.radius * g->as.capsule.radius) {
            ga2d__ray_circle(g->as.capsule.center1, g->as.capsule.radius, p, u, &best); /* ends that coincide */
        }
        break;
    case GA2D_SHAPE_POLYGON:
        ga2d__polygon_hull(&g->as.polygon, ga2d_transform_identity(), 1, &h);
        if (h.radius > 0)
            ga2d__ray_round(&h, p, u, &best);
        else
            ga2d__ray_sharp(&h, p, u, &best);
        break;
    default: {
        const ga2d_segment *s = ga2d__segment_of(g);
        ga2d__ray_segment(s->point1, s->point2, g->type == GA2D_SHAPE_CHAIN_SEGMENT, p, u, &best);
        break;
    }
    }
    /* a piece whose arithmetic overflowed (a shape's coordinates near the
       real range) answers NaN, which every comparison above lets by: no hit */
    if (!best.hit || !(best.t >= 0 && best.t <= len) || !ga2d__finite_vec(best.normal)) return out;
    out.hit = 1;
    out.fraction = best.t / len;
    if (out.fraction > 1) out.fraction = 1; /* t <= len; the quotient may round past */
    out.point = ga2d__ray_point(ga2d_vec_add(p, ga2d_vec_scale(u, best.t)), p, d, out.fraction);
    out.normal = best.normal;
    return out;
}

/* The input checks of ga2d_collide_shapes, for a ray. */
static ga2d_result ga2d__ray_input(const ga2d_geometry *g, ga2d_vec origin, ga2d_vec translation)
{
    int bad = ga2d__geometry_input(g);
    if (bad) return (ga2d_result)-bad;
    if (!ga2d__finite_vec(origin) || !ga2d__finite_vec(translation) || !ga2d__finite_vec(ga2d_vec_add(origin, translation)))
        return GA2D_ERR_NOT_FINITE;
    if (translation.x == 0 && translation.y == 0) return GA2D_ERR_INVALID_ARGUMENT;
    return GA2D_OK;
}

static ga2d_ray_result ga2d__ray_cast_local(const ga2d_geometry *g, ga2d_vec origin, ga2d_vec translation)
{
    ga2d_ray_result none;
    if (ga2d__ray_input(g, origin, translation) != GA2D_OK) {
        memset(&none, 0, sizeof none);
        return none;
    }
    return ga2d__ray_geometry(g, origin, translation);
}

GA2D_API ga2d_ray_result ga2d_ray_cast_circle(const ga2d_circle *c, ga2d_vec origin, ga2d_vec translation)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = c ? GA2D_SHAPE_CIRCLE : GA2D_SHAPE_TYPE_COUNT;
    if (c) g.as.circle = *c;
    return ga2d__ray_cast_local(&g, origin, translation);
}

GA2D_API ga2d_ray_result ga2d_ray_cast_capsule(const ga2d_capsule *c, ga2d_vec origin, ga2d_vec translation)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = c ? GA2D_SHAPE_CAPSULE : GA2D_SHAPE_TYPE_COUNT;
    if (c) g.as.capsule = *c;
    return ga2d__ray_cast_local(&g, origin, translation);
}

GA2D_API ga2d_ray_result ga2d_ray_cast_polygon(const ga2d_polygon *p, ga2d_vec origin, ga2d_vec translation)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = p ? GA2D_SHAPE_POLYGON : GA2D_SHAPE_TYPE_COUNT;
    if (p) g.as.polygon = *p;
    return ga2d__ray_cast_local(&g, origin, translation);
}

GA2D_API ga2d_ray_result ga2d_ray_cast_segment(const ga2d_segment *s, ga2d_vec origin, ga2d_vec translation, int one_sided)
{
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = !s ? GA2D_SHAPE_TYPE_COUNT : one_sided ? GA2D_SHAPE_CHAIN_SEGMENT : GA2D_SHAPE_SEGMENT;
    if (s && one_sided) {
        g.as.chain_segment.segment = *s;
        g.as.chain_segment.ghost1 = s->point1; /* ghosts play no part in a ray cast */
        g.as.chain_segment.ghost2 = s->point2;
    } else if (s) {
        g.as.segment = *s;
    }
    return ga2d__ray_cast_local(&g, origin, translation);
}

/* The ray taken into g's frame by x^-1 (origin less x.p, then turned
   back: no large coordinate enters the shape's arithmetic), and its hit
   brought back by x. */
static ga2d_ray_result ga2d__ray_placed(const ga2d_geometry *g, ga2d_transform x, ga2d_vec origin, ga2d_vec translation)
{
    ga2d_ray_result r = ga2d__ray_geometry(g, ga2d_transform_apply_inv(x, origin), ga2d_rotate_inv(x.q, translation));
    if (r.hit) {
        r.point = ga2d__ray_point(ga2d_transform_apply(x, r.point), origin, translation, r.fraction);
        r.normal = ga2d_rotate(x.q, r.normal);
    }
    return r;
}

GA2D_API ga2d_result ga2d_ray_cast_shape(const ga2d_geometry *g, ga2d_transform x, ga2d_vec origin, ga2d_vec translation,
                                         ga2d_ray_result *out)
{
    ga2d_result r = ga2d__ray_input(g, origin, translation);
    if (r == GA2D_OK && !out) r = GA2D_ERR_INVALID_ARGUMENT;
    if (r == GA2D_OK && ga2d__collide_input(x, x, 1)) r = (ga2d_result)-ga2d__collide_input(x, x, 1);
    if (r != GA2D_OK) return r;
    *out = ga2d__ray_placed(g, x, origin, translation);
    return GA2D_OK;
}

/* ------------------------------------------------------------------- GJK */
/* Closest points of two convex proxies by GJK (Gilbert, Johnson and
   Keerthi): the simplex of B - A's support points that is nearest the
   origin, grown toward it one support point at a time.  Worked in A's
   frame, so B's placement relative to A is all that is rounded. */
typedef struct ga2d__sv {
    ga2d_vec wa, wb, w; /* A's support point, B's, and w = wb - wa, a point of B - A */
    ga2d_real a;        /* its weight in the closest point */
    int ia, ib;
} ga2d__sv;
typedef struct ga2d__simplex { ga2d__sv v[3]; int count; } ga2d__simplex;

/* The index of the point of p[0..n-1] farthest along d (the first of equals). */
static int ga2d__support(const ga2d_vec *p, int n, ga2d_vec d)
{
    int best = 0, i;
    ga2d_real m = ga2d_dot(p[0], d);
    for (i = 1; i < n; ++i) {
        ga2d_real s = ga2d_dot(p[i], d);
        if (s > m) {
            m = s;
            best = i;
        }
    }
    return best;
}

static ga2d__sv ga2d__sv_make(const ga2d_vec *pa, int ia, const ga2d_vec *pb, int ib, ga2d_vec shift_b)
{
    ga2d__sv s;
    s.ia = ia;
    s.ib = ib;
    s.wa = pa[ia];
    s.wb = ga2d_vec_add(pb[ib], shift_b);
    s.w = ga2d_vec_sub(s.wb, s.wa);
    s.a = 1;
    return s;
}

/* The closest point of a segment w1 w2 to the origin by its Voronoi
   regions: past w1 (d2 <= 0), past w2 (d1 <= 0), or between, weighted by
   the distances from the origin's foot to the far end. */
static void ga2d__solve2(ga2d__simplex *s)
{
    ga2d_vec w1 = s->v[0].w, w2 = s->v[1].w, e = ga2d_vec_sub(w2, w1);
    ga2d_real d1 = ga2d_dot(w2, e), d2 = -ga2d_dot(w1, e);
    if (d2 <= 0) {
        s->v[0].a = 1;
        s->count = 1;
    } else if (d1 <= 0) {
        s->v[0] = s->v[1];
        s->v[0].a = 1;
        s->count = 1;
    } else {
        s->v[0].a = d1 / (d1 + d2);
        s->v[1].a = d2 / (d1 + d2);
    }
}

/* The same for a triangle: its vertices' and edges' regions, by the dot
   products above and the signed areas (wedges) of the origin with each
   edge against the triangle's own; inside all three edges the origin is
   in the triangle (count stays 3: the cores overlap). */
static void ga2d__solve3(ga2d__simplex *s)
{
    ga2d_vec w1 = s->v[0].w, w2 = s->v[1].w, w3 = s->v[2].w;
    ga2d_vec e12 = ga2d_vec_sub(w2, w1), e13 = ga2d_vec_sub(w3, w1), e23 = ga2d_vec_sub(w3, w2);
    ga2d_real d12_1 = ga2d_dot(w2, e12), d12_2 = -ga2d_dot(w1, e12);
    ga2d_real d13_1 = ga2d_dot(w3, e13), d13_2 = -ga2d_dot(w1, e13);
    ga2d_real d23_1 = ga2d_dot(w3, e23), d23_2 = -ga2d_dot(w2, e23);
    ga2d_real n = ga2d_wedge(e12, e13);
    ga2d_real d123_1 = n * ga2d_wedge(w2, w3), d123_2 = n * ga2d_wedge(w3, w1), d123_3 = n * ga2d_wedge(w1, w2);
    if (d12_2 <= 0 && d13_2 <= 0) { /* w1 */
        s->v[0].a = 1;
        s->count = 1;
    } else if (d12_1 > 0 && d12_2 > 0 && d123_3 <= 0) { /* edge 12 */
        s->v[0].a = d12_1 / (d12_1 + d12_2);
        s->v[1].a = d12_2 / (d12_1 + d12_2);
        s->count = 2;
    } else if (d13_1 > 0 && d13_2 > 0 && d123_2 <= 0) { /* edge 13 */
        s->v[0].a = d13_1 / (d13_1 + d13_2);
        s->v[2].a = d13_2 / (d13_1 + d13_2);
        s->v[1] = s->v[2];
        s->count = 2;
    } else if (d12_1 <= 0 && d23_2 <= 0) { /* w2 */
        s->v[0] = s->v[1];
        s->v[0].a = 1;
        s->count = 1;
    } else if (d13_1 <= 0 && d23_1 <= 0) { /* w3 */
        s->v[0] = s->v[2];
        s->v[0].a = 1;
        s->count = 1;
    } else if (d23_1 > 0 && d23_2 > 0 && d123_1 <= 0) { /* edge 23 */
        s->v[0] = s->v[2];
        s->v[0].a = d23_2 / (d23_1 + d23_2);
        s->v[1].a = d23_1 / (d23_1 + d23_2);
        s->count = 2;
    } else { /* inside: each vertex weighs its opposite part's area over the
                whole's, n (the quotients of the wedges themselves: the
                products d123 underflow to 0 for a triangle of 1e-10 m in
                float, and 0 / 0 made the closest points NaN) */
        s->v[0].a = n != 0 ? ga2d_wedge(w2, w3) / n : (ga2d_real)1 / 3;
        s->v[1].a = n != 0 ? ga2d_wedge(w3, w1) / n : (ga2d_real)1 / 3;
        s->v[2].a = n != 0 ? ga2d_wedge(w1, w2) / n : (ga2d_real)1 / 3;
    }
}

static ga2d_vec ga2d__simplex_point(const ga2d__simplex *s, int which) /* 0: w, 1: wa, 2: wb */
{
    ga2d_vec p = ga2d_vec_make(0, 0);
    int i;
    for (i = 0; i < s->count; ++i) {
        ga2d_vec v = which == 0 ? s->v[i].w : which == 1 ? s->v[i].wa : s->v[i].wb;
        p = ga2d_vec_add(p, ga2d_vec_scale(v, s->v[i].a));
    }
    return p;
}

/* Toward the origin from the simplex: from a point, back at it; from a
   segment, square off it on the origin's side (exact even when the
   origin's foot is rounded off the segment). */
static ga2d_vec ga2d__search_direction(const ga2d__simplex *s)
{
    if (s->count == 1) return ga2d_vec_neg(s->v[0].w);
    {
        ga2d_vec e = ga2d_vec_sub(s->v[1].w, s->v[0].w);
        return ga2d_wedge(e, ga2d_vec_neg(s->v[0].w)) > 0 ? ga2d_vec_perp(e) : ga2d_vec_neg(ga2d_vec_perp(e));
    }
}

/* GJK on point sets pa (count na) and pb (count nb, shifted by shift_b),
   one frame, from the cached simplex or from the first points.  Returns
   the final simplex (count 3: the cores overlap) and its iterations. */
static int ga2d__gjk(const ga2d_vec *pa, int na, const ga2d_vec *pb, int nb, ga2d_vec shift_b, ga2d_simplex_cache *cache,
                     ga2d__simplex *s)
{
    int iter = 0, i;
    s->count = 0;
    if (cache && cache->count >= 1 && cache->count <= 3) {
        for (i = 0; i < cache->count; ++i) {
            if (cache->index_a[i] >= na || cache->index_b[i] >= nb) break;
            s->v[i] = ga2d__sv_make(pa, cache->index_a[i], pb, cache->index_b[i], shift_b);
        }
        s->count = i == cache->count ? i : 0;
    }
    if (s->count == 0) {
        s->v[0] = ga2d__sv_make(pa, 0, pb, 0, shift_b);
        s->count = 1;
    }
    while (iter < GA2D_GJK_MAX_ITERATIONS) {
        int old_a[3], old_b[3], old = s->count, dup = 0;
        ga2d_vec d;
        ga2d__sv nv;
        for (i = 0; i < old; ++i) {
            old_a[i] = s->v[i].ia;
            old_b[i] = s->v[i].ib;
        }
        if (s->count == 2) ga2d__solve2(s);
        if (s->count == 3) ga2d__solve3(s);
        if (s->count == 3) break; /* the origin is inside */
        d = ga2d__search_direction(s);
        if (ga2d_dot(d, d) < GA2D__MIN_NORMAL) break; /* the origin is on the simplex */
        nv = ga2d__sv_make(pa, ga2d__support(pa, na, ga2d_vec_neg(d)), pb, ga2d__support(pb, nb, d), shift_b);
        ++iter;
        for (i = 0; i < old; ++i) dup |= nv.ia == old_a[i] && nv.ib == old_b[i];
        if (dup) break; /* no new support point: the simplex is nearest */
        /* no progress toward the origin along d: nearest within rounding */
        if (ga2d_dot(nv.w, d) <= ga2d_dot(ga2d__simplex_point(s, 0), d)) break;
        s->v[s->count++] = nv;
    }
    if (s->count == 1) s->v[0].a = 1;
    if (cache) {
        cache->count = s->count;
        for (i = 0; i < s->count; ++i) {
            cache->index_a[i] = (uint8_t)s->v[i].ia;
            cache->index_b[i] = (uint8_t)s->v[i].ib;
        }
    }
    return iter;
}

GA2D_API ga2d_shape_proxy ga2d_make_proxy(const ga2d_vec *points, int count, ga2d_real radius)
{
    ga2d_shape_proxy p;
    int i;
    memset(&p, 0, sizeof p);
    if (!points || count < 1) return p;
    if (count > GA2D_MAX_POLYGON_VERTICES) count = GA2D_MAX_POLYGON_VERTICES;
    for (i = 0; i < count; ++i) p.points[i] = points[i];
    p.count = count;
    p.radius = radius;
    return p;
}

GA2D_API ga2d_shape_proxy ga2d_shape_proxy_of(const ga2d_geometry *g)
{
    ga2d_vec pts[2];
    ga2d_shape_proxy none;
    memset(&none, 0, sizeof none);
    if (!g) return none;
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE: return ga2d_make_proxy(&g->as.circle.center, 1, g->as.circle.radius);
    case GA2D_SHAPE_CAPSULE:
        pts[0] = g->as.capsule.center1;
        pts[1] = g->as.capsule.center2;
        return ga2d_make_proxy(pts, 2, g->as.capsule.radius);
    case GA2D_SHAPE_POLYGON: return ga2d_make_proxy(g->as.polygon.vertices, g->as.polygon.count, g->as.polygon.radius);
    case GA2D_SHAPE_SEGMENT:
    case GA2D_SHAPE_CHAIN_SEGMENT: {
        const ga2d_segment *s = ga2d__segment_of(g);
        pts[0] = s->point1;
        pts[1] = s->point2;
        return ga2d_make_proxy(pts, 2, 0);
    }
    default: return none;
    }
}

static ga2d_result ga2d__proxy_input(const ga2d_shape_proxy *p)
{
    int i;
    if (!p || p->count < 1 || p->count > GA2D_MAX_POLYGON_VERTICES) return GA2D_ERR_INVALID_ARGUMENT;
    for (i = 0; i < p->count; ++i)
        if (!ga2d__finite_vec(p->points[i])) return GA2D_ERR_NOT_FINITE;
    if (!ga2d__finite(p->radius)) return GA2D_ERR_NOT_FINITE;
    return p->radius < 0 ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK;
}

static ga2d_result ga2d__pair_input(const ga2d_shape_proxy *a, ga2d_transform xa, const ga2d_shape_proxy *b, ga2d_transform xb)
{
    ga2d_result r = ga2d__proxy_input(a);
    int bad;
    if (r == GA2D_OK) r = ga2d__proxy_input(b);
    if (r != GA2D_OK) return r;
    bad = ga2d__collide_input(xa, xb, 1);
    return bad ? (ga2d_result)-bad : GA2D_OK;
}

/* B's points in A's frame. */
static void ga2d__proxy_in(const ga2d_shape_proxy *b, ga2d_transform rel, ga2d_vec *out)
{
    int i;
    for (i = 0; i < b->count; ++i) out[i] = ga2d_transform_apply(rel, b->points[i]);
}

/* Closest points in A's frame (see ga2d_shape_distance). */
static ga2d_distance_result ga2d__distance(const ga2d_shape_proxy *a, const ga2d_shape_proxy *b, ga2d_transform rel,
                                           ga2d_simplex_cache *cache)
{
    ga2d_distance_result out;
    ga2d_vec pb[GA2D_MAX_POLYGON_VERTICES], pa, qb, n;
    ga2d__simplex s;
    ga2d_real d, radii = a->radius + b->radius;
    ga2d__proxy_in(b, rel, pb);
    out.iterations = ga2d__gjk(a->points, a->count, pb, b->count, ga2d_vec_make(0, 0), cache, &s);
    pa = ga2d__simplex_point(&s, 1);
    qb = ga2d__simplex_point(&s, 2);
    d = s.count == 3 ? 0 : ga2d_vec_normalize(ga2d_vec_sub(qb, pa), &n);
    if (d == 0) n = ga2d_vec_make(0, 0);
    if (d > radii) {
        out.point_a = ga2d_vec_add(pa, ga2d_vec_scale(n, a->radius));
        out.point_b = ga2d_vec_sub(qb, ga2d_vec_scale(n, b->radius));
        out.distance = d - radii;
    } else { /* touching or overlapping: the middle of the cores' closest points */
        out.point_a = out.point_b = ga2d_vec_scale(ga2d_vec_add(pa, qb), GA2D__R(0.5));
        out.distance = 0;
    }
    out.normal = n;
    return out;
}

GA2D_API ga2d_result ga2d_shape_distance(const ga2d_shape_proxy *a, ga2d_transform xa, const ga2d_shape_proxy *b,
                                         ga2d_transform xb, ga2d_simplex_cache *cache, ga2d_distance_result *out)
{
    ga2d_result r = ga2d__pair_input(a, xa, b, xb);
    ga2d_distance_result d;
    if (r == GA2D_OK && !out) r = GA2D_ERR_INVALID_ARGUMENT;
    if (r != GA2D_OK) return r;
    d = ga2d__distance(a, b, ga2d_transform_inv_mul(xa, xb), cache);
    out->point_a = ga2d_transform_apply(xa, d.point_a);
    out->point_b = ga2d_transform_apply(xa, d.point_b);
    out->normal = ga2d_rotate(xa.q, d.normal);
    out->distance = d.distance;
    out->iterations = d.iterations;
    return GA2D_OK;
}

/* ------------------------------------------------------------ shape cast */
/* B moved by lambda r, in A's frame: conservative advancement along r
   (van den Bergen's GJK ray cast).  The support points of A toward B and
   of B toward A along the current direction u bound the gap along u;
   lambda moves to where that gap, closing at -u.r per unit of lambda,
   would reach 0, and the simplex restarts there.  The gap never closes
   before that, so lambda never passes the touching one. */
static ga2d_ray_result ga2d__shape_cast(const ga2d_shape_proxy *a, const ga2d_shape_proxy *b, ga2d_transform rel, ga2d_vec r,
                                        ga2d_real tol)
{
    ga2d_ray_result out;
    ga2d_vec pb[GA2D_MAX_POLYGON_VERTICES], v, n = ga2d_vec_make(0, 0), shift = ga2d_vec_make(0, 0);
    ga2d__simplex s;
    ga2d_real lambda = 0, radii = a->radius + b->radius;
    int iter, i;
    memset(&out, 0, sizeof out);
    ga2d__proxy_in(b, rel, pb);
    s.v[0] = ga2d__sv_make(a->points, ga2d__support(a->points, a->count, r), pb, ga2d__support(pb, b->count, ga2d_vec_neg(r)),
                           shift);
    s.count = 1;
    v = s.v[0].w;
    for (iter = 0; iter < GA2D_GJK_MAX_ITERATIONS; ++iter) {
        ga2d_vec u;
        ga2d__sv nv;
        ga2d_real len = ga2d_vec_normalize(v, &u), gap, closing;
        int dup = 0;
        if (len - radii <= tol) break; /* within the tolerance of touching */
        nv = ga2d__sv_make(a->points, ga2d__support(a->points, a->count, u), pb, ga2d__support(pb, b->count, ga2d_vec_neg(u)),
                           shift);
        gap = ga2d_dot(u, nv.w) - radii;
        if (gap > 0) {
            closing = -ga2d_dot(u, r);
            if (!(closing > 0)) return out; /* apart along u, and not closing: never touch */
            lambda += gap / closing;
            if (!(lambda <= 1)) return out; /* past the end, or NaN (values near the real range overflowed) */
            shift = ga2d_vec_scale(r, lambda);
            nv = ga2d__sv_make(a->points, nv.ia, pb, nv.ib, shift);
            n = u;
            s.count = 0;
        }
        for (i = 0; i < s.count; ++i) dup |= nv.ia == s.v[i].ia && nv.ib == s.v[i].ib;
        if (dup) break; /* nothing nearer: the gap is as small as it gets here */
        s.v[s.count++] = nv;
        if (s.count == 2) ga2d__solve2(&s);
        if (s.count == 3) ga2d__solve3(&s);
        if (s.count == 3) break; /* the cores meet (radii 0, or touching at the start) */
        if (s.count == 1) s.v[0].a = 1;
        v = ga2d__simplex_point(&s, 0);
    }
    /* where they are: the closest points of the simplex, A's surface */
    {
        ga2d_vec pa = ga2d__simplex_point(&s, 1), qb = ga2d__simplex_point(&s, 2), m;
        if (s.count < 3 && ga2d_vec_normalize(ga2d_vec_sub(qb, pa), &m) > 0) n = m;
        else if (lambda == 0) n = ga2d_vec_make(0, 0); /* the cores overlap at the start */
        out.point = ga2d_vec_add(pa, ga2d_vec_scale(n, a->radius));
    }
    out.normal = n;
    out.fraction = lambda;
    out.hit = 1;
    return out;
}

GA2D_API ga2d_result ga2d_shape_cast(const ga2d_shape_proxy *a, ga2d_transform xa, const ga2d_shape_proxy *b,
                                     ga2d_transform xb, ga2d_vec translation, ga2d_ray_result *out)
{
    ga2d_result r = ga2d__pair_input(a, xa, b, xb);
    ga2d_ray_result c;
    if (r == GA2D_OK && !out) r = GA2D_ERR_INVALID_ARGUMENT;
    if (r == GA2D_OK && !ga2d__finite_vec(translation)) r = GA2D_ERR_NOT_FINITE;
    if (r != GA2D_OK) return r;
    c = ga2d__shape_cast(a, b, ga2d_transform_inv_mul(xa, xb), ga2d_rotate_inv(xa.q, translation),
                         GA2D__R(GA2D_LINEAR_SLOP) / 4);
    if (c.hit) {
        c.point = ga2d_transform_apply(xa, c.point);
        c.normal = ga2d_rotate(xa.q, c.normal);
    }
    *out = c;
    return GA2D_OK;
}

/* -------------------------------------------------------- time of impact */
GA2D_API ga2d_transform ga2d_sweep_transform(const ga2d_sweep *s, ga2d_real t)
{
    ga2d_transform x;
    ga2d_vec c;
    if (!s) return ga2d_transform_identity();
    c = ga2d_vec_add(s->c1, ga2d_vec_scale(ga2d_vec_sub(s->c2, s->c1), t));
    x.q = ga2d_rotor_from_angle(s->a1 + t * (s->a2 - s->a1));
    x.p = ga2d_vec_sub(c, ga2d_rotate(x.q, s->local_center));
    return x;
}

/* The farthest any point of p's core lies from the centre c (its frame). */
static ga2d_real ga2d__reach(const ga2d_shape_proxy *p, ga2d_vec c)
{
    ga2d_real m = 0;
    int i;
    for (i = 0; i < p->count; ++i) {
        ga2d_real d = ga2d_vec_length(ga2d_vec_sub(p->points[i], c));
        if (d > m) m = d;
    }
    return m;
}

static int ga2d__sweep_ok(const ga2d_sweep *s)
{
    return s && ga2d__finite_vec(s->local_center) && ga2d__finite_vec(s->c1) && ga2d__finite_vec(s->c2) && ga2d__finite(s->a1) &&
           ga2d__finite(s->a2);
}

GA2D_API ga2d_result ga2d_time_of_impact(const ga2d_shape_proxy *a, const ga2d_sweep *sa, const ga2d_shape_proxy *b,
                                         const ga2d_sweep *sb, ga2d_real target, ga2d_real t_max, ga2d_toi_result *out)
{
    ga2d_result r = ga2d__proxy_input(a);
    ga2d_simplex_cache cache;
    ga2d_real t = 0, tol = GA2D__R(GA2D_LINEAR_SLOP) / 4, reach_a, reach_b, turn_a, turn_b;
    ga2d_vec dca, dcb;
    int iter;
    if (r == GA2D_OK) r = ga2d__proxy_input(b);
    if (r == GA2D_OK && (!sa || !sb || !out)) r = GA2D_ERR_INVALID_ARGUMENT;
    if (r == GA2D_OK && (!ga2d__sweep_ok(sa) || !ga2d__sweep_ok(sb) || !ga2d__finite(target) || !ga2d__finite(t_max)))
        r = GA2D_ERR_NOT_FINITE;
    if (r == GA2D_OK && (target < 0 || !(t_max > 0) || t_max > 1)) r = GA2D_ERR_INVALID_ARGUMENT;
    if (r != GA2D_OK) return r;
    memset(&cache, 0, sizeof cache);
    reach_a = ga2d__reach(a, sa->local_center);
    reach_b = ga2d__reach(b, sb->local_center);
    turn_a = GA2D__FABS(sa->a2 - sa->a1);
    turn_b = GA2D__FABS(sb->a2 - sb->a1);
    dca = ga2d_vec_sub(sa->c2, sa->c1);
    dcb = ga2d_vec_sub(sb->c2, sb->c1);
    for (iter = 0; iter < GA2D_TOI_MAX_ITERATIONS; ++iter) {
        ga2d_transform xa = ga2d_sweep_transform(sa, t), xb = ga2d_sweep_transform(sb, t);
        ga2d_distance_result d = ga2d__distance(a, b, ga2d_transform_inv_mul(xa, xb), &cache);
        ga2d_vec n = ga2d_rotate(xa.q, d.normal);
        /* the fastest the gap can close per unit t: the centres' approach
           along n, and any point's turn about its centre at most its
           reach times the turn (an arc is no longer than that) */
        ga2d_real closing = -ga2d_dot(n, ga2d_vec_sub(dcb, dca)) + reach_a * turn_a + reach_b * turn_b;
        out->iterations = iter + 1;
        if (d.distance <= target + tol) {
            out->state = t == 0 ? GA2D_TOI_OVERLAPPED : GA2D_TOI_HIT;
            out->t = t;
            return GA2D_OK;
        }
        if (!(closing > 0)) break; /* it cannot close: apart for good */
        t += (d.distance - target) / closing;
        if (t >= t_max) break;
    }
    if (iter == GA2D_TOI_MAX_ITERATIONS) {
        out->state = GA2D_TOI_GAVE_UP;
        out->t = t;
        return GA2D_OK;
    }
    out->state = GA2D_TOI_SEPARATED;
    out->t = t_max;
    return GA2D_OK;
}

/* ======================================================== world and bodies */
/* A touching manifold as ga2d__collide last made it, in A's frame, for
   ga2d__reuse_manifold: B's placement in that frame then (xa^-1 xb), the
   normal, each point (midway between the surfaces) and its separation.
   Valid while the contact touches. */
typedef struct ga2d__held {
    ga2d_transform rel;
    ga2d_vec normal, point[2];
    ga2d_real separation[2];
} ga2d__held;

/* A contact joins two bodies whose fat boxes overlap.  Contacts live in a
   pool (stable index, free list) and on both bodies' lists: link value
   2 * contact + side, side 0 on body a's list and 1 on body b's. */
typedef struct ga2d__contact {
    /* first: what walking a body's list reads (the solver's order walks
       every list each step) and what says which shapes it joins, in one
       cache line */
    int a, b;                /* body slots: shape_a's body, shape_b's */
    int prev[2], next[2];    /* the bodies' list links, -1 at the ends */
    int touching;
    int next_free;           /* -2 while in use */
    int flags;               /* GA2D__CONTACT_*: what the narrowphase found, until book-kept */
    int shape_a, shape_b;    /* shape slots, shape_a < shape_b */
    int extras;              /* a shape is round, a conveyor, rolls with resistance or reports hits */
    /* what listing the touching contacts reads of each (ga2d__touch_holds,
       ga2d__order_constraints): at the back of the record, the two
       random passes over the contacts read two lines of each */
    uint64_t serial;         /* creation order (snapshots rebuild the lists by it) */
    uint64_t boxes_checked;  /* world->box_clock when its fat boxes were last seen to overlap (0: never) */
    ga2d_real friction, restitution;
    ga2d_manifold manifold;
    ga2d_vec end_normal;     /* an ended touch's new normal, while its end is reported */
    ga2d_real peak[2];       /* each point's largest normal impulse in the last step (hit events) */
    ga2d__held held;         /* the manifold in A's frame, while touching */
} ga2d__contact;

/* Asks for the front of a contact's record, through `restitution`: what
   the narrowphase and listing the touching contacts read first.  The
   records (240 bytes in float) start 0, 16, 32 or 48 bytes into a cache
   line, so those 72 bytes lie on the record's first two lines. */
#define GA2D__PREFETCH_CONTACT(ct)                                                                                      \
    do {                                                                                                               \
        GA2D__PREFETCH_READ(ct);                                                                                       \
        GA2D__PREFETCH_READ((const char *)(ct) + 64);                                                                  \
    } while (0)

/* A touching contact in the solver's canonical order: by A's slot, then
   by creation (ga2d__update_touches). */
typedef struct ga2d__touch {
    int a, contact;
    uint64_t serial;
} ga2d__touch;

/* What the narrowphase stage found of a contact, for the book-keeping
   after it (ga2d__contact.flags; zero between steps). */
#define GA2D__CONTACT_DISJOINT 1 /* the fat boxes parted: destroy it */
#define GA2D__CONTACT_BEGAN 2    /* began touching */
#define GA2D__CONTACT_ENDED 4    /* stopped touching: its last touching manifold kept for the event */
#define GA2D__CONTACT_WAKES 8    /* touches a sleeping body */

static uint64_t ga2d__pair_key(int a, int b) { return ((uint64_t)(uint32_t)a << 32) | (uint32_t)b; }

static uint32_t ga2d__hash(uint64_t k)
{
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdull;
    k ^= k >> 33;
    k *= 0xc4ceb9fe1a85ec53ull;
    k ^= k >> 33;
    return (uint32_t)k;
}

/* A body's integration state: what the integrators and the solver's
   set-up read and write each step, apart from the shapes.  State is kept at
   the centre of mass (position `center`, orientation `q`, velocity `v`,
   angular velocity `w` of Omega = w e12); the origin that users see is
   center - local_center q. */
typedef struct ga2d__body_sim {
    ga2d_vec center;
    ga2d_rotor q;
    ga2d_vec v;
    ga2d_real w;
    ga2d_vec center0;            /* where the step began (solver) */
    ga2d_vec dp;                 /* center - center0 as the substeps moved it, kept apart from
                                    center's rounding (ga2d__drift) */
    ga2d_rotor q0;
    ga2d_rotor dq;               /* q q0~: its turn since then, per solver pass */
    ga2d_real inv_mass, inv_inertia;
    ga2d_vec force;              /* the user's, cleared after each step */
    ga2d_real torque;
    ga2d_real gravity_scale, linear_damping, angular_damping;
    ga2d_vec local_center;
    ga2d_vec field_force;        /* the force callback's, per evaluation */
    ga2d_real field_torque;
    ga2d_vec field_accel;        /* Verlet: the field's acceleration at the */
    ga2d_real field_alpha;       /* current state, reused by the next step */
    int field_valid;
} ga2d__body_sim;

/* A body slot, in three parts as they are used: its integration state
   (`sim`, first, so the integrators' reads share the fewest cache lines);
   its book-keeping (identity, lists, island, sleep); and its mass, the
   sum over its shapes (ga2d__shape).  The solver's view of it is
   ga2d__sbody, with the solver. */
typedef struct ga2d__body {
    /* what the per-body stages test, beside the state they read */
    int type;                    /* ga2d_body_type; -1 for a free slot */
    int awake;
    int move_index;              /* index in world->moving, or -1 */
    uint64_t boxes_changed;      /* world->box_clock when its shapes' fat boxes last changed */
    ga2d__body_sim sim;
    /* book-keeping */
    uint32_t generation;
    int next_free;
    int contact_head;            /* first (oldest) link of its contact list, or -1 */
    int contact_tail;            /* last (newest) link, or -1 */
    int shape_head, shape_tail;  /* its shapes in creation order (ga2d__shape.next), or -1 */
    int joint_head;              /* its newest joint link (ga2d__joint.next), or -1 */
    int shape_count;
    int island;                  /* union-find parent while islands form */
    int wake_request;            /* asleep, pushed by the force field: wakes at the step's end */
    ga2d_real sleep_time, island_rest;
    void *user_data;
    /* its mass */
    ga2d_real mass, inertia;
    int fixed_rotation;
    ga2d_real extent;            /* the farthest its shapes reach from the centre */
    ga2d_real min_extent;        /* its thinnest shape's inner reach (continuous collision) */
    int is_bullet;
    ga2d_real box_slack;         /* how far its shapes can go and stay in their tree boxes, as last
                                    found at a step's start, less its motion since (-1: unknown) */
    ga2d_real box_excess;        /* how far its boxes reach past its shapes at most, then, plus that motion */
} ga2d__body;

/* A chain slot: its body and its segments' shape slots, in order. */
typedef struct ga2d__chain {
    int type;                    /* 0 live, -1 free */
    uint32_t generation;
    int next_free;
    int body;
    int *shapes;
    int count;
} ga2d__chain;

/* A shape slot: a body's piece of geometry, in the body's frame, with its
   material and filter; it has the broadphase proxy, and contacts join
   shapes.  Shapes live in a pool (stable index, free list) and on their
   body's list. */
typedef struct ga2d__shape {
    int type;                    /* ga2d_shape_type; -1 for a free slot */
    uint32_t generation;
    int next_free;
    int body;                    /* its body's slot */
    int next;                    /* the next shape of its body, or -1 */
    int proxy;                   /* leaf in trees[tree] */
    int tree;                    /* 1 on a moving body, 0 on a static one */
    int in_move;                 /* queued for pair finding */
    ga2d_real radius;            /* its round part's (ga2d__shape_radius), kept for the solver */
    ga2d_real density, friction, restitution;
    ga2d_filter filter;
    void *user_data;
    int is_sensor, sensor_events, pre_solve_events, hit_events;
    ga2d_real tangent_speed, rolling_resistance;
    int chain;                   /* a chain segment's chain slot, else -1 */
    int *visitors;               /* a sensor's: the shapes overlapping it, ascending */
    int visitor_count, visitor_capacity;
    ga2d_geometry geom;
} ga2d__shape;

/* The solver's types, defined with the solver; the step context holds
   them by pointer. */
typedef struct ga2d__contact_constraint ga2d__contact_constraint;
typedef struct ga2d__group ga2d__group;
typedef struct ga2d__fill { int count, skip; } ga2d__fill;
/* What a stage over the bodies counts (ga2d__run_counted). */
typedef struct ga2d__counts { int speed_caps, rotation_updates, integrated_bodies, unfinite, boxes_kept; } ga2d__counts;
typedef struct ga2d__group_extra ga2d__group_extra;
typedef struct ga2d__sbody ga2d__sbody;
typedef struct ga2d__kbody ga2d__kbody;
typedef struct ga2d__lane_key ga2d__lane_key;
typedef struct ga2d__joint_seen ga2d__joint_seen;
typedef struct ga2d__joint ga2d__joint;
typedef struct ga2d__jgroup ga2d__jgroup;
typedef struct ga2d__rk4 ga2d__rk4;
/* A stretch of every solver pass (ga2d__segments): joints [joint_begin,
   joint_end), then lane groups [group_begin, group_end); shared with the
   workers in `blocks` blocks (joint_blocks of GA2D__JOINT_BLOCK joints,
   then of GA2D__GROUP_BLOCK groups), or run as one block, in order. */
typedef struct ga2d__segment {
    int joint_begin, joint_end, group_begin, group_end;
    int shared, joint_blocks, blocks;
} ga2d__segment;
#define GA2D__SEGMENTS (2 * GA2D__COLOURS + 3) /* two a colour at most, the overflow's and the rest */

/* A soft constraint: a spring of `hertz` and damping ratio `zeta` seen by
   an implicit step of h, as a bias rate and the scales of mass and of the
   accumulated impulse (Catto's soft step). */
typedef struct ga2d__soft { ga2d_real bias_rate, mass_scale, impulse_scale; } ga2d__soft;

/* A joint slot (the joints section has what it does).  Joints live in a
   pool as bodies and shapes do, each on both its bodies' joint lists. */
struct ga2d__joint {
    /* what every pass reads first, together (a pass over thousands of
       joints streams them: the solver's fields span two cache lines) */
    int type;                    /* ga2d_joint_type; -1 for a free slot */
    int body[2];                 /* A's and B's slots */
    int enable_limit, enable_motor, enable_spring;
    int lane;                    /* 1 + its lane among the step's hinge lanes (ga2d__jgroup)
                                    from their filling to their impulses' store, else 0 */
    uint64_t serial;             /* creation order: the solver's order (read with the
                                    fields above as the step lists its joints) */
    /* impulses per substep, kept from step to step to warm start: the
       point's (or the motor joint's linear), the axial ones (spring,
       motor, limits: along the angle, or the distance joint's axis), and
       the rigid axial one (distance: the length; weld and motor joint:
       the angle) */
    ga2d_vec linear_impulse;
    ga2d_real spring_impulse, motor_impulse, lower_impulse, upper_impulse, impulse;
    /* prepared each step: the anchors from the centres (world frame) and
       the centres' offset, where the step began; the angle then, less the
       reference (0 where no pass reads it); the masses and springs */
    ga2d_vec ra, rb, delta_center;
    ga2d_real delta_angle;
    ga2d_real ima, imb, iia, iib, axial_mass;
    ga2d_vec target;             /* motor joint: the offset in the world frame, step start */
    ga2d__soft spring, linear_spring;
    /* what the kinds' defs set, shared where they mean the same:
       reference_angle  B's angle less A's at rest (revolute, weld), or
                        the target one (motor joint: angular_offset)
       lower, upper     the limit: angles (revolute), lengths (distance)
       motor_speed      rad/s (revolute), m/s (distance)
       max_motor        N m (revolute), N (distance)
       hertz, damping_ratio  the spring (revolute, distance; weld: angular)
       length           distance: the rest length
       linear_hertz, linear_damping_ratio  weld: the linear spring
       offset           motor joint: where B's anchor is driven, from A's,
                        in A's frame (linear_offset)
       max_force, max_torque, correction  motor joint */
    ga2d_real reference_angle, lower, upper, motor_speed, max_motor, hertz, damping_ratio;
    ga2d_real length, linear_hertz, linear_damping_ratio, max_force, max_torque, correction;
    ga2d_vec offset;
    /* the pool's and the lists' */
    uint32_t generation;
    int next_free;
    int next[2];                 /* the next link on body[side]'s list, or -1 */
    ga2d_vec local[2];           /* anchors in the bodies' frames, from their origins */
    int collide_connected;
    void *user_data;
};


/* What a step computes and throws away, apart from the world's lasting
   state: the step's times, the contact softness, what it will report, and
   the solver's arrays (kept between steps only to reuse their memory).
   Every stage reads and writes the world through it. */
typedef struct ga2d__step_context {
    ga2d_world *world;
    ga2d_real dt;                /* this step's dt (the last one's between steps) */
    ga2d_real h, inv_h;          /* the substep and its inverse */
    double t0, t;                /* world time at the step's and the substep's start */
    ga2d__soft soft, stiff;      /* contacts between moving bodies, and against a fixed one */
    ga2d__soft joint_soft;       /* a rigid joint's position feedback */
    int joint_bias_in_relax;     /* the PGS kinds' velocity passes push joints together too */
    int *joint_order;            /* the step's joints (pool slots): in creation order, then by colour */
    int joint_order_capacity, joint_active;
    ga2d__lane_key *joint_keys;  /* each step joint's bodies and sides moved (ga2d__joint_key), in
                                    joint_order's creation order, from ga2d__prepare_joints */
    int joint_key_capacity;
    ga2d__joint_seen *joint_seen; /* per joint slot, what ga2d__see_joints found of it */
    int joint_seen_capacity;
    int *joint_sorted;           /* scratch while joints are coloured: the order by colour */
    int joint_sorted_capacity;
    int *joint_perm;             /* the colour order as positions in creation order (kept with the colouring) */
    int joint_perm_capacity;
    int *joint_colours;          /* scratch while joints are coloured: each one's, in creation order */
    int joint_colour_capacity;
    int joint_start[GA2D__COLOURS + 1]; /* the joint each colour begins at; [colour_count]: the overflow's */
    int joint_bare[GA2D__COLOURS + 1]; /* each colour's bare hinges, first in its joints */
    ga2d__jgroup *jgroups;       /* bare hinges in lanes (ga2d__pack_hinges), live during the substeps */
    int jgroup_count, jgroup_capacity;
    int *joint_lane;             /* by place in joint_order while jgroups live: 1 + its lane, or 0 */
    int joint_lane_capacity;
    int masses_stale;            /* the solver bodies have moved since the warm start or a pass found
                                    the lanes' anchors and masses (ga2d__wfind) */
    int scatter_due;             /* the relax pass's velocities are still only the solver bodies'
                                    (ga2d__stage_defer_scatter) */
    ga2d__kbody *kbodies;        /* by moving index, while the substeps integrate on the solver bodies */
    int kbody_capacity;
    int compact;                 /* they do (ga2d__compact_begin): the bodies are behind until
                                    ga2d__compact_end */
    int compact_fresh;           /* the first kick loads them first (ga2d__kload) */
    int *kicked;                 /* by slot, in restitution: the impulses applied when it last took one */
    int kicked_capacity;
    ga2d_result error;           /* what the step will report */
    int end_lost;                /* a sensor end event since the last step found no room: reported
                                    as OUT_OF_MEMORY after the step, which runs in full (its
                                    stages read `error` as their own failures) */
    int *order;                  /* the contacts to solve (pool indices), in canonical order */
    int order_capacity;
    unsigned char *touch_seen;   /* per touching contact, what ga2d__see_touches found */
    int touch_seen_capacity;
    ga2d__contact_constraint *constraints; /* theirs, in that order */
    int constraint_count, constraint_capacity;
    int bouncy;                  /* of them, those with restitution: none, and the bounce passes are skipped */
    ga2d__group *groups;         /* the lane solver's, live during the substeps */
    int group_count, group_capacity;
    ga2d__fill *fill;            /* beside each group while lanes are assigned: its lanes in use,
                                    and when full a later group to look at first */
    int fill_capacity;
    ga2d__group_extra *group_extras; /* beside the groups, when a constraint needs them */
    int group_extra_capacity, group_extras_on;
    ga2d__sbody *sbodies;        /* its body state, by slot (one dummy past the end) */
    int sbody_capacity;
    int *last_group;             /* by slot: the last overflow group that moves the body */
    int last_group_capacity;
    int *lane_constraints;       /* by lane (group * GA2D__LANES + lane): its constraint */
    int lane_constraint_capacity;
    uint32_t *colour_masks;      /* by slot while lanes are assigned: the colours that move the body */
    int colour_mask_capacity;
    int colour_count;            /* colours in use this step */
    int colour_start[GA2D__COLOURS + 1]; /* the group each colour begins at; [colour_count]: the overflow's */
    ga2d__lane_key *lane_keys;   /* the last colouring's constraints, as it read them (ga2d__lanes_kept) */
    int lane_key_capacity;
    int lane_key_count;          /* how many (constraints, then joints); -1: no colouring is kept */
    int kept_groups, kept_colours, kept_joints; /* its groups, colours and joints */
    int *still_slots;            /* the bodies its constraints do not move (once each, mostly) */
    int still_count, still_capacity;
    ga2d__rk4 *rk4;              /* RK4's scratch, one per moving body's capacity */
    int rk4_capacity;
    uint64_t *changed;           /* a bit per pool contact the narrowphase flagged */
    int changed_capacity;        /* in 64-bit words */
    uint64_t *refits;            /* a bit per moving body whose tree leaf holds a new box */
    uint64_t *fast;              /* a bit per moving body ga2d__continuous sweeps */
    int fast_capacity;           /* in 64-bit words */
    ga2d__tree *stray_tree;      /* the tree ga2d__flag_strays looks through */
    int refit_capacity;          /* in 64-bit words */
    ga2d__counts *counts;        /* a body stage's counts per block (ga2d__run_counted) */
    int counts_capacity, counts_split;
    int unfinite;                /* bodies the last counted stage left with a velocity not finite */
    int *tally;                  /* a count per block of a split stage's items (a range writes
                                    its first block's), summed after it */
    int tally_capacity;
    ga2d__segment segments[GA2D__SEGMENTS]; /* the solver passes' (ga2d__segments) */
    int segment_count;
    int *team_lines;             /* the workers' team's counters (ga2d__team) */
    int team_line_capacity;
    ga2d_real rk4_at, rk4_weight; /* the RK4 stage under way: its time in substeps, its weight */
} ga2d__step_context;

/* A stage of the step over items [begin, end) of its kind (moving bodies,
   contacts, constraints or lane groups).  A stage only computes: what
   creates, destroys or wakes is book-kept after it, in order.  Its items
   write their own data, so a range is a unit of work (threads will hand
   ranges to workers), except for three shared writes threads must still
   split: the world's counters, containment of a body gone non-finite,
   and a body the solver does not move, written into the solver bodies by
   each lane that has it (the same values). */
typedef void ga2d__range_fn(ga2d__step_context *c, int begin, int end);

/* Runs a stage over all n items. */
static void ga2d__run(ga2d__step_context *c, ga2d__range_fn *fn, int n)
{
    if (n > 0) fn(c, 0, n);
}

/* A stage whose items write only their own data (and whole 64-bit words
   of the step's bit sets) runs in ranges on the user's workers: the task
   system sees blocks of GA2D__SPLIT_BLOCK items, so no two ranges share a
   word.  Below GA2D__SPLIT_MIN items it is not worth a hand-off: what
   the other core writes must come back to this one's cache for the
   stages after, a line at a time (500 ns a round trip between the two
   cores of the machine measured), and a narrowphase of about 420
   contacts handed over made mixed_bin (103 bodies) 0.78-0.80 times as
   fast on two workers as on one, pyramid20 (210 boxes) 0.87-0.90; with
   the minimum at 1024 both ran at 0.99-1.01.  A
   colour of the solver's goes in blocks of GA2D__GROUP_BLOCK lane groups
   (each GA2D__LANES constraints) and of GA2D__JOINT_BLOCK joints, when it
   has GA2D__COLOUR_MIN groups' worth: a group's pass takes about 0.1 us
   and a hinge's about 20 ns (joint_grid: 6.5 ms a step for 12 passes
   over 19 794 joints), so a block of either is a couple of us, and a
   hand-off a few (pyramid20, 210 boxes, stepped at 0.42 times one
   worker's speed on two when every colour of two blocks was handed
   over). */
#define GA2D__SPLIT_BLOCK 64
#define GA2D__SPLIT_MIN 1024
#define GA2D__SPLIT_MIN_BLOCKS 2
#define GA2D__GROUP_BLOCK 4
#define GA2D__JOINT_BLOCK 16
#define GA2D__COLOUR_MIN 64
typedef struct ga2d__task {
    ga2d__step_context *c;
    ga2d__range_fn *fn;
    int begin, end, block;       /* the items, and how many a block holds */
} ga2d__task;

static void ga2d__task_entry(int start, int end, int worker, void *context)
{
    const ga2d__task *t = (const ga2d__task *)context;
    int begin = t->begin + start * t->block, stop = t->begin + end * t->block;
    (void)worker;
    if (stop > t->end) stop = t->end;
    if (begin < stop) t->fn(t->c, begin, stop);
}

static void ga2d__run_split(ga2d__step_context *c, ga2d__range_fn *fn, int n);

struct ga2d_world {
    ga2d_world_def def;          /* as resolved at creation, kept current */
    ga2d__body *bodies;
    int body_capacity, body_used, body_count, free_head;
    ga2d__shape *shapes;
    int shape_capacity, shape_used, shape_count, shape_free;
    ga2d__chain *chains;
    int chain_capacity, chain_used, chain_count, chain_free;
    ga2d__joint *joints;
    int joint_capacity, joint_used, joint_count, joint_free;
    uint64_t joint_serial;       /* the last joint's creation serial */
    int sensor_count;            /* live sensor shapes: none, and sensing costs nothing */
    int hit_shapes;              /* live shapes with hit events: none, and no pass looks for hits */
    ga2d_sensor_event *sensor_begin, *sensor_end;
    int sensor_begin_count, sensor_end_count, sensor_begin_capacity, sensor_end_capacity;
    int sensor_end_pending;      /* ends from destruction since the last step */
    int sensor_end_lost;         /* one of those found no room: the next step says so */
    int *sensor_scratch;         /* a sensor's candidates this step */
    int sensor_scratch_count, sensor_scratch_capacity;
    int *moving;                 /* slots of kinematic and dynamic bodies */
    int moving_count, moving_capacity;
    int moving_dynamic;          /* of them dynamic: the awake bodies counters report */
    double time, eval_time;
    int lock;                    /* GA2D__LOCK_* bits: why changes are refused now */
    int depth;                   /* entry points under way that may run user code */
    int wake_requests;           /* bodies with wake_request set, this step */
    int destroy_pending;         /* ga2d_world_destroy came from user code: at depth 0 */
    ga2d_allocator mem;          /* the user's allocator behind the lock (ga2d__hook_alloc) */
    uint32_t tag;                /* this world's mark in its body ids */
    ga2d_world_counters counters;
    /* broadphase: trees[0] static bodies, trees[1] moving ones */
    ga2d__tree trees[2];
    uint64_t box_clock;          /* one more after each step's narrowphase (ga2d__collide_contacts):
                                    when a body's boxes changed, when a contact's were checked */
    int *move_buf;               /* shapes queued for pair finding */
    int move_count, move_capacity;
    uint64_t *new_pairs;
    int new_pair_count, new_pair_capacity;
    /* contacts: a pool, and the set of pairs that have one */
    ga2d__contact *contacts;
    int contact_capacity, contact_used, contact_free, contact_count;
    int touching_count;          /* contacts with manifold points: the counter, kept as they flip */
    uint64_t contact_serial;     /* the next contact's */
    ga2d__touch *touches, *touches_next; /* the touching contacts, canonical order, kept step to step */
    int touch_count, touch_capacity, touch_next_capacity;
    int touches_known;           /* 0: rebuilt by walking the bodies' lists at the next listing */
    int *began;                  /* contacts that began touching since the last listing */
    int began_count, began_capacity;
    uint64_t *pair_keys;         /* the pair set (ga2d__pairs_has) */
    int pair_capacity;           /* holds contact_count keys: one per contact */
    ga2d_contact_data *begin_events, *end_events;
    int begin_count, end_count, begin_capacity, end_capacity;
    ga2d_contact_hit_event *hit_events;
    int hit_count, hit_capacity;
    ga2d_real slop, speculative, aabb_margin; /* scaled by length units */
    ga2d__step_context step;
    int error_slot;              /* the lowest slot the last step contained, or -1 */
    int *wake_queue;             /* one entry per body slot */
    int wake_capacity;
};

/* Items [begin, end) of a split stage, in blocks of `block`: on the
   user's workers when the world has them and there are at least
   GA2D__SPLIT_MIN_BLOCKS blocks, else here. */
static void ga2d__run_blocks(ga2d__step_context *c, ga2d__range_fn *fn, int begin, int end, int block)
{
    const ga2d_world *w = c->world;
    ga2d__task t;
    void *handle;
    int blocks = (end - begin + block - 1) / block;
    if (end <= begin) return;
    if (w->def.worker_count <= 1 || !w->def.enqueue_task || blocks < GA2D__SPLIT_MIN_BLOCKS) {
        fn(c, begin, end);
        return;
    }
    t.c = c;
    t.fn = fn;
    t.begin = begin;
    t.end = end;
    t.block = block;
    handle = w->def.enqueue_task(ga2d__task_entry, blocks, 1, &t, w->def.user_task_context);
    if (handle) w->def.finish_task(handle, w->def.user_task_context);
}

/* A split stage over all n items: not worth a hand-off below
   GA2D__SPLIT_MIN. */
static void ga2d__run_split(ga2d__step_context *c, ga2d__range_fn *fn, int n)
{
    if (n < GA2D__SPLIT_MIN) ga2d__run(c, fn, n);
    else ga2d__run_blocks(c, fn, 0, n, GA2D__SPLIT_BLOCK);
}

/* A stage over the moving bodies that counts (ga2d__counts) rather than
   writing the world's counters, and leaves a body whose velocity is no
   longer finite to be contained after it: one body's update reads no
   other's, so containing it later changes nothing, and the stage can run
   in ranges on the workers.  A range hands its counts here (inlined, so
   that its stage keeps them in registers). */
static GA2D__HOT void ga2d__counts_add(ga2d__step_context *c, const ga2d__counts *n)
{
    ga2d_world *w = c->world;
    w->counters.speed_caps += n->speed_caps;
    w->counters.rotation_updates += n->rotation_updates;
    w->counters.integrated_bodies += n->integrated_bodies;
    w->counters.boxes_kept += n->boxes_kept;
    c->unfinite += n->unfinite;
}
static GA2D__HOT void ga2d__counts_put(ga2d__step_context *c, int begin, const ga2d__counts *n)
{
    if (c->counts_split) c->counts[begin / GA2D__SPLIT_BLOCK] = *n; /* a range's own slot (ranges start on blocks) */
    else ga2d__counts_add(c, n);
}

/* Why a world refuses changes: the bits of ga2d_world.lock.  User code
   runs inside the library at four places (the force callback, the debug
   draw's callbacks, the allocator's hooks, and a world being destroyed or
   loaded); from there, reads are safe and every change is refused with
   GA2D_ERR_LOCKED, except forces from the force callback, which is what it
   is for. */
#define GA2D__LOCK_STEP 1   /* inside ga2d_world_step */
#define GA2D__LOCK_FIELD 2  /* inside the force callback */
#define GA2D__LOCK_DRAW 4   /* inside a debug-draw callback */
#define GA2D__LOCK_ALLOC 8  /* inside the user's allocator, or a world being loaded */
#define GA2D__LOCK_DEAD 16  /* being destroyed */
#define GA2D__LOCK_QUERY 32 /* inside a world query's callback */

/* The world's allocations go through these, so that user code in an
   allocator hook finds the world locked. */
static void *ga2d__hook_alloc(size_t size, void *ctx)
{
    ga2d_world *w = (ga2d_world *)ctx;
    int lock = w->lock;
    void *p;
    if (!w->def.allocator.alloc) return malloc(size);
    GA2D_ASSERT(w->depth > 0); /* every entry point that allocates is bracketed */
    w->lock |= GA2D__LOCK_ALLOC;
    p = w->def.allocator.alloc(size, w->def.allocator.ctx);
    w->lock = lock;
    return p;
}

static void ga2d__hook_free(void *ptr, size_t size, void *ctx)
{
    ga2d_world *w = (ga2d_world *)ctx;
    int lock = w->lock;
    if (!w->def.allocator.free) {
        free(ptr);
        return;
    }
    GA2D_ASSERT(w->depth > 0);
    w->lock |= GA2D__LOCK_ALLOC;
    w->def.allocator.free(ptr, size, w->def.allocator.ctx);
    w->lock = lock;
}

static void ga2d__destroy_now(ga2d_world *w);

/* An entry point that may run user code (a callback, an allocator hook)
   brackets that part with enter/leave; a world destroyed from the user
   code goes when the outermost one leaves.  Nothing may touch w after
   ga2d__leave. */
static void ga2d__enter(ga2d_world *w) { ++w->depth; }
static void ga2d__leave(ga2d_world *w)
{
    if (--w->depth == 0 && w->destroy_pending) ga2d__destroy_now(w);
}

GA2D_API ga2d_body_id ga2d_body_id_null(void) { ga2d_body_id id; id.index1 = 0; id.generation = 0; return id; }
GA2D_API int ga2d_body_id_is_null(ga2d_body_id id) { return id.index1 == 0; }
GA2D_API int ga2d_body_id_equal(ga2d_body_id a, ga2d_body_id b) { return a.index1 == b.index1 && a.generation == b.generation; }

/* A world's mark in its ids: the id's generation is the slot's generation
   xor this, so an id from another world is refused (unless two live
   worlds' 32-bit tags collide, odds 2^-32).  Taken from the world's
   address (the library keeps no global counter); a snapshot carries it,
   so the ids of a saved world stay valid in the world that loads it. */
static uint32_t ga2d__world_tag(const ga2d_world *w) { return ga2d__hash((uint64_t)(uintptr_t)w); }

/* The slot an id names (the null id's is -1); ga2d__lookup checks it. */
static int ga2d__slot(ga2d_body_id id) { return (int)id.index1 - 1; }

/* Slots.  Bodies, shapes and chains live in pools: an entry's `type` is
   -1 while its slot is free, and its `generation` counts the slot's
   reuses.  An id is the slot + 1 and the generation mixed with the world's
   tag.  The entry an id names, or NULL: null, out-of-range, free and
   reused slots, and another world's ids are all refused here. */
static void *ga2d__live_slot(void *pool, size_t size, int used, size_t type_at, size_t generation_at, uint32_t tag,
                             uint32_t index1, uint32_t generation)
{
    unsigned char *entry;
    int type;
    uint32_t g;
    if (index1 == 0 || index1 > (uint32_t)used) return NULL;
    entry = (unsigned char *)pool + (size_t)(index1 - 1) * size;
    memcpy(&type, entry + type_at, sizeof type);
    memcpy(&g, entry + generation_at, sizeof g);
    return type < 0 || (g ^ tag) != generation ? NULL : entry;
}
#define GA2D__LIVE(w, T, pool, used, id)                                                                               \
    ((w) ? (T *)ga2d__live_slot((w)->pool, sizeof(T), (w)->used, offsetof(T, type), offsetof(T, generation), (w)->tag, \
                                (id).index1, (id).generation)                                                          \
         : (T *)NULL)

/* The generation a freed slot takes: never 0, so no id of a live entry
   is ever the null one's. */
static uint32_t ga2d__next_generation(uint32_t g) { return g + 1 ? g + 1 : 1; }

/* The live body an id names, or NULL. */
static ga2d__body *ga2d__lookup(const ga2d_world *w, ga2d_body_id id)
{
    return GA2D__LIVE(w, ga2d__body, bodies, body_used, id);
}

/* Position, rotor and velocities all finite. */
static int ga2d__state_finite(const ga2d__body_sim *b)
{
    return ga2d__finite_vec(b->center) && ga2d__finite(b->q.c) && ga2d__finite(b->q.s) && ga2d__finite_vec(b->v) &&
           ga2d__finite(b->w);
}

/* Refuses a change while the world is stepping. */
static ga2d_result ga2d__writable(const ga2d_world *w, ga2d_body_id id, ga2d__body **out)
{
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    *out = ga2d__lookup(w, id);
    return *out ? GA2D_OK : GA2D_ERR_STALE_ID;
}

static void ga2d__wake(ga2d_world *w, int slot);
static void ga2d__put_to_sleep(ga2d_world *w, int slot);
static int ga2d__flip_island(ga2d_world *w, int slot, int from);
static void ga2d__lane_clear(ga2d__step_context *c, int lane);
static void ga2d__contain(ga2d_world *w, int slot);
static int ga2d__reserve_rk4(ga2d_world *w, int n);
static int ga2d__reserve_moving(ga2d_world *w, int n);
static int ga2d__reserve_slots(ga2d_world *w, int n);
static void ga2d__step_release(ga2d_world *w);
static void ga2d__step_free(const ga2d_allocator *a, ga2d__step_context *c);
static void ga2d__update_sleep(ga2d__step_context *c);
static int ga2d__joined_apart(const ga2d_world *w, int a, int b);
static void ga2d__joint_free(ga2d_world *w, int k);
static void ga2d__joints_forget(ga2d_world *w, int slot);

/* ------------------------------------------------------------- pair set */
/* Which shape pairs have a contact: a set of keys, open addressing,
   linear probing, kept at most half full; key 0 marks an empty slot (a
   real key has a < b).  Only whether a pair is there is ever asked (a
   re-queried shape meets mostly the pairs it has), so the set holds the
   keys alone: one cache line a look. */
static int ga2d__pairs_has(const ga2d_world *w, uint64_t key)
{
    uint32_t mask, i;
    if (!w->pair_capacity) return 0;
    mask = (uint32_t)w->pair_capacity - 1;
    for (i = ga2d__hash(key) & mask; w->pair_keys[i]; i = (i + 1) & mask)
        if (w->pair_keys[i] == key) return 1;
    return 0;
}

static void ga2d__pairs_put(uint64_t *keys, int cap, uint64_t key)
{
    uint32_t mask = (uint32_t)cap - 1, i;
    for (i = ga2d__hash(key) & mask; keys[i]; i = (i + 1) & mask) {}
    keys[i] = key;
}

/* Room for one more pair; 0 when memory runs out (nothing changed). */
static int ga2d__pairs_reserve(ga2d_world *w)
{
    int cap = w->pair_capacity ? w->pair_capacity : 64, i;
    uint64_t *keys;
    if (2 * (w->contact_count + 1) <= w->pair_capacity) return 1;
    while (2 * (w->contact_count + 1) > cap) cap *= 2;
    keys = (uint64_t *)ga2d__alloc(&w->mem, (size_t)cap * sizeof *keys);
    if (!keys) return 0;
    memset(keys, 0, (size_t)cap * sizeof *keys);
    for (i = 0; i < w->pair_capacity; ++i)
        if (w->pair_keys[i]) ga2d__pairs_put(keys, cap, w->pair_keys[i]);
    {
        uint64_t *old_keys = w->pair_keys;
        int old_cap = w->pair_capacity;
        w->pair_keys = keys;
        w->pair_capacity = cap;
        ga2d__free(&w->mem, old_keys, (size_t)old_cap * sizeof *keys);
    }
    return 1;
}

/* Deletion by backward shift keeps every probe chain unbroken. */
static void ga2d__pairs_remove(ga2d_world *w, uint64_t key)
{
    uint32_t mask = (uint32_t)w->pair_capacity - 1, i, j;
    for (i = ga2d__hash(key) & mask; w->pair_keys[i] != key; i = (i + 1) & mask) GA2D_ASSERT(w->pair_keys[i]);
    for (j = (i + 1) & mask; w->pair_keys[j]; j = (j + 1) & mask) {
        uint32_t home = ga2d__hash(w->pair_keys[j]) & mask;
        /* move j back to i unless its home lies cyclically in (i, j] */
        if (((j - home) & mask) >= ((j - i) & mask)) {
            w->pair_keys[i] = w->pair_keys[j];
            i = j;
        }
    }
    w->pair_keys[i] = 0;
}

/* ------------------------------------------------------ contact lifetime */
/* A body's list holds its contacts oldest first: a new one goes at the
   tail (the solver takes them in this order, see ga2d__order_constraints). */
static void ga2d__link_contact(ga2d_world *w, int ci, int side)
{
    ga2d__contact *c = &w->contacts[ci];
    ga2d__body *b = &w->bodies[side ? c->b : c->a];
    c->prev[side] = b->contact_tail;
    c->next[side] = -1;
    if (b->contact_tail >= 0) w->contacts[b->contact_tail >> 1].next[b->contact_tail & 1] = 2 * ci + side;
    else b->contact_head = 2 * ci + side;
    b->contact_tail = 2 * ci + side;
}

static void ga2d__unlink_contact(ga2d_world *w, int ci, int side)
{
    ga2d__contact *c = &w->contacts[ci];
    ga2d__body *b = &w->bodies[side ? c->b : c->a];
    if (c->prev[side] >= 0) w->contacts[c->prev[side] >> 1].next[c->prev[side] & 1] = c->next[side];
    else b->contact_head = c->next[side];
    if (c->next[side] >= 0) w->contacts[c->next[side] >> 1].prev[c->next[side] & 1] = c->prev[side];
    else b->contact_tail = c->prev[side];
}

/* Friction mixes as sqrt(mu_a mu_b), restitution as max(e_a, e_b). */
/* A body's edges, oldest first: the links of its contact list (joints
   will join them).  Islands, waking and the solver's canonical order all
   walk them so: for (l = first_edge; l >= 0; l = next_edge). */
static int ga2d__first_edge(const ga2d_world *w, int slot) { return w->bodies[slot].contact_head; }
static int ga2d__next_edge(const ga2d_world *w, int link) { return w->contacts[link >> 1].next[link & 1]; }
/* The body at an edge's other end. */
static int ga2d__edge_other(const ga2d_world *w, int link)
{
    const ga2d__contact *c = &w->contacts[link >> 1];
    return (link & 1) ? c->a : c->b;
}

/* x, or the largest real of its sign where it overflowed: two legal
   materials can multiply or add past the range (an infinite cap times a
   zero impulse is NaN, and a NaN bound clamps nothing). */
static ga2d_real ga2d__saturate(ga2d_real x) { return x > GA2D__MAX ? GA2D__MAX : (x < -GA2D__MAX ? -GA2D__MAX : x); }

/* A contact's friction: the geometric mean of its shapes' frictions.
   Each is finite, and so is the mean, but their product can overflow (a
   friction near the largest real against one above 1): an infinite
   friction's cap on a tangent impulse is inf * 0 = NaN while the normal
   impulse is 0, which clamps nothing, and the world's own snapshot is
   refused (a contact's friction must be finite).  So an overflowing
   product takes the mean root by root (the two roundings may carry it
   just past the largest real: kept at that); a finite one is rooted as
   ever, the same bits. */
static ga2d_real ga2d__mix_friction(ga2d_real a, ga2d_real b)
{
    ga2d_real p = a * b;
    if (ga2d__finite(p)) return GA2D__SQRT(p);
    return ga2d__saturate(GA2D__SQRT(a) * GA2D__SQRT(b));
}

/* A contact for the shape pair sa < sb (their bodies differ). */
static int ga2d__create_contact(ga2d_world *w, int sa, int sb)
{
    const ga2d__shape *pa = &w->shapes[sa], *pb = &w->shapes[sb];
    int a = pa->body, b = pb->body;
    ga2d__contact *c;
    int ci;
    if (!ga2d__pairs_reserve(w)) return 0;
    if (w->contact_free >= 0) {
        ci = w->contact_free;
        w->contact_free = w->contacts[ci].next_free;
    } else {
        if (!ga2d__grow(&w->mem, (void **)&w->contacts, &w->contact_capacity, w->contact_used + 1,
                        sizeof *w->contacts))
            return 0;
        ci = w->contact_used++;
    }
    c = &w->contacts[ci];
    memset(c, 0, sizeof *c);
    c->a = a;
    c->b = b;
    c->shape_a = sa;
    c->shape_b = sb;
    c->next_free = -2;
    c->serial = w->contact_serial++;
    c->friction = ga2d__mix_friction(pa->friction, pb->friction);
    c->restitution = pa->restitution > pb->restitution ? pa->restitution : pb->restitution;
    c->extras = pa->radius != 0 || pb->radius != 0 || pa->tangent_speed != 0 || pb->tangent_speed != 0 ||
                pa->rolling_resistance != 0 || pb->rolling_resistance != 0 || pa->hit_events || pb->hit_events;
    ga2d__link_contact(w, ci, 0);
    ga2d__link_contact(w, ci, 1);
    ga2d__pairs_put(w->pair_keys, w->pair_capacity, ga2d__pair_key(sa, sb));
    ++w->contact_count;
    return 1;
}

static void ga2d__destroy_contact(ga2d_world *w, int ci)
{
    ga2d__contact *c = &w->contacts[ci];
    ga2d__unlink_contact(w, ci, 0);
    ga2d__unlink_contact(w, ci, 1);
    ga2d__pairs_remove(w, ga2d__pair_key(c->shape_a, c->shape_b));
    w->touching_count -= c->touching;
    c->next_free = w->contact_free;
    w->contact_free = ci;
    --w->contact_count;
}

static ga2d_body_id ga2d__id_of(const ga2d_world *w, int slot)
{
    ga2d_body_id id;
    id.index1 = (uint32_t)slot + 1;
    id.generation = w->bodies[slot].generation ^ w->tag;
    return id;
}

static ga2d_shape_id ga2d__shape_id_of(const ga2d_world *w, int k)
{
    ga2d_shape_id id;
    id.index1 = (uint32_t)k + 1;
    id.generation = w->shapes[k].generation ^ w->tag;
    return id;
}

/* The live shape an id names, or NULL. */
static ga2d__shape *ga2d__shape_lookup(const ga2d_world *w, ga2d_shape_id id)
{
    return GA2D__LIVE(w, ga2d__shape, shapes, shape_used, id);
}

static void ga2d__contact_data(const ga2d_world *w, const ga2d__contact *c, ga2d_contact_data *out)
{
    out->body_a = ga2d__id_of(w, c->a);
    out->body_b = ga2d__id_of(w, c->b);
    out->manifold = c->manifold;
    out->shape_a = ga2d__shape_id_of(w, c->shape_a);
    out->shape_b = ga2d__shape_id_of(w, c->shape_b);
}

/* Appends an event; on failure the step reports OUT_OF_MEMORY. */
static void ga2d__push_event(ga2d_world *w, int end, const ga2d__contact *c)
{
    ga2d_contact_data **arr = end ? &w->end_events : &w->begin_events;
    int *count = end ? &w->end_count : &w->begin_count, *cap = end ? &w->end_capacity : &w->begin_capacity;
    if (!ga2d__grow(&w->mem, (void **)arr, cap, *count + 1, sizeof **arr)) {
        w->step.error = GA2D_ERR_OUT_OF_MEMORY;
        return;
    }
    ga2d__contact_data(w, c, &(*arr)[(*count)++]);
}

static int ga2d__cmp_contact_serial(const void *x, const void *y)
{
    uint64_t a = ((const ga2d__contact *)x)->serial, b = ((const ga2d__contact *)y)->serial;
    return (a > b) - (a < b);
}

/* The live contacts move into a pool of their own size, oldest first, and
   the pair set is rebuilt at the capacity they need; every body's list is
   relinked in that order, which is the order it had (each list holds its
   contacts oldest first).  Everything is allocated before anything
   changes: 0 (out of memory) leaves the world as it was. */
static void ga2d__release(ga2d_world *w, void **arr, int *cap, size_t elem);
static int ga2d__contacts_compact(ga2d_world *w)
{
    int n = w->contact_count, cap = 64, i, k = 0;
    ga2d__contact *pool = NULL, *old = w->contacts;
    uint64_t *keys, *old_keys = w->pair_keys;
    int old_cap = w->contact_capacity, old_pairs = w->pair_capacity;
    while (2 * n > cap) cap *= 2;
    keys = (uint64_t *)ga2d__alloc(&w->mem, (size_t)cap * sizeof *keys);
    pool = keys && n > 0 ? (ga2d__contact *)ga2d__alloc(&w->mem, (size_t)n * sizeof *pool) : NULL;
    if (!keys || (n > 0 && !pool)) {
        ga2d__free(&w->mem, keys, (size_t)cap * sizeof *keys);
        return 0;
    }
    for (i = 0; i < w->contact_used; ++i)
        if (old[i].next_free == -2) pool[k++] = old[i];
    if (n > 1) qsort(pool, (size_t)n, sizeof *pool, ga2d__cmp_contact_serial);
    memset(keys, 0, (size_t)cap * sizeof *keys);
    for (i = 0; i < n; ++i) ga2d__pairs_put(keys, cap, ga2d__pair_key(pool[i].shape_a, pool[i].shape_b));
    w->contacts = pool;
    w->contact_capacity = n;
    w->contact_used = n;
    w->contact_free = -1;
    w->pair_keys = keys;
    w->pair_capacity = cap;
    for (i = 0; i < w->body_used; ++i) w->bodies[i].contact_head = w->bodies[i].contact_tail = -1;
    for (i = 0; i < n; ++i) {
        ga2d__link_contact(w, i, 0);
        ga2d__link_contact(w, i, 1);
    }
    /* the touching list names pool slots: walked again at the next step */
    ga2d__release(w, (void **)&w->touches, &w->touch_capacity, sizeof *w->touches);
    ga2d__release(w, (void **)&w->touches_next, &w->touch_next_capacity, sizeof *w->touches_next);
    ga2d__release(w, (void **)&w->began, &w->began_capacity, sizeof *w->began);
    w->touch_count = w->began_count = w->touches_known = 0;
    ga2d__free(&w->mem, old, (size_t)old_cap * sizeof *old);
    ga2d__free(&w->mem, old_keys, (size_t)old_pairs * sizeof *keys);
    return 1;
}

/* Frees an array and zeroes its capacity (the step grows it again). */
static void ga2d__release(ga2d_world *w, void **arr, int *cap, size_t elem)
{
    void *p = *arr;
    size_t bytes = (size_t)*cap * elem;
    *arr = NULL;
    *cap = 0;
    ga2d__free(&w->mem, p, bytes);
}

static ga2d_result ga2d__compact(ga2d_world *w)
{
    int k;
    if (!ga2d__contacts_compact(w)) return GA2D_ERR_OUT_OF_MEMORY;
    /* what can be found again is forgotten: the boxes' slack too, so that
       a compacted world takes every body's boxes from its shapes */
    for (k = 0; k < w->body_used; ++k) w->bodies[k].box_slack = -1;
    ga2d__release(w, (void **)&w->new_pairs, &w->new_pair_capacity, sizeof *w->new_pairs);
    ga2d__step_release(w);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_compact(ga2d_world *w)
{
    ga2d_result r;
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    ga2d__enter(w);
    r = ga2d__compact(w);
    ga2d__leave(w);
    return r;
}

/* ------------------------------------------------------------- filtering */
GA2D_API ga2d_filter ga2d_default_filter(void)
{
    ga2d_filter f;
    f.category_bits = 1;
    f.mask_bits = 0xFFFFFFFFu;
    f.group_index = 0;
    return f;
}

GA2D_API int ga2d_should_collide(ga2d_filter a, ga2d_filter b)
{
    if (a.group_index == b.group_index && a.group_index != 0) return a.group_index > 0;
    return (a.category_bits & b.mask_bits) != 0 && (b.category_bits & a.mask_bits) != 0;
}

/* A pair of shapes gets a contact when they are on two bodies, a dynamic
   one among them (static and kinematic bodies do not push each other),
   and the filters allow it. */
static int ga2d__pair_wanted(const ga2d_world *w, int i, int j)
{
    const ga2d__shape *si = &w->shapes[i], *sj = &w->shapes[j];
    const ga2d__body *a = &w->bodies[si->body], *b = &w->bodies[sj->body];
    if (si->body == sj->body || si->is_sensor || sj->is_sensor) return 0;
    if (a->type != GA2D_BODY_DYNAMIC && b->type != GA2D_BODY_DYNAMIC) return 0;
    if (!ga2d_should_collide(si->filter, sj->filter)) return 0; /* two ANDs before the joint walk */
    return !(w->joint_count > 0 && ga2d__joined_apart(w, si->body, sj->body));
}

/* ---------------------------------------------------------- proxies */
static ga2d_aabb ga2d__fatten(ga2d_aabb b, ga2d_real m)
{
    b.lower.x -= m;
    b.lower.y -= m;
    b.upper.x += m;
    b.upper.y += m;
    return b;
}

/* A body's origin, the point users place it by: its centre less the
   centre's offset turned by q (c - l q). */
static GA2D__HOT ga2d_vec ga2d__body_origin(const ga2d__body *b) { return ga2d_vec_sub(b->sim.center, ga2d_rotate(b->sim.q, b->sim.local_center)); }

static GA2D__HOT ga2d_transform ga2d__body_xf(const ga2d__body *b) { return ga2d_transform_make(ga2d__body_origin(b), b->sim.q); }

/* The tree a shape's proxy lives in: static bodies' or moving ones'. */
static ga2d__tree *ga2d__tree_of(const ga2d_world *w, const ga2d__shape *s) { return (ga2d__tree *)&w->trees[s->tree]; }

/* A shape's fat box, as its tree holds it. */
static ga2d_aabb ga2d__fat_box(const ga2d_world *w, const ga2d__shape *s) { return ga2d__tree_of(w, s)->nodes[s->proxy].box; }

/* Queue a shape for pair finding (capacity is kept >= the shape slots). */
static void ga2d__buffer_move(ga2d_world *w, int shape)
{
    if (w->shapes[shape].in_move) return;
    w->shapes[shape].in_move = 1;
    GA2D_ASSERT(w->move_count < w->move_capacity);
    w->move_buf[w->move_count++] = shape;
}

/* Queue every shape of a body. */
static void ga2d__buffer_body(ga2d_world *w, int slot)
{
    int s;
    for (s = w->bodies[slot].shape_head; s >= 0; s = w->shapes[s].next) ga2d__buffer_move(w, s);
}

/* A body's fat-box margin: GA2D_AABB_MARGIN, or a quarter of its extent
   if that is less.  The margin saves re-fits of a body that jiggles in
   place; it costs pairs, and a small body packed among its like meets
   every neighbour within two margins of it: 0.2 m boxes in a pile made
   10-12 pairs each with the full 0.1 m, for 3-4 that touch. */
#define GA2D__MARGIN_PER_EXTENT 0.25
static ga2d_real ga2d__margin(const ga2d_world *w, const ga2d__body *b)
{
    ga2d_real rel = GA2D__R(GA2D__MARGIN_PER_EXTENT) * b->extent;
    return rel < w->aabb_margin ? rel : w->aabb_margin;
}

/* The box a body can reach within a step: its AABB swept along v dt, and
   grown by how far a vertex can swing (extent |w| dt, at most the
   extent).  Forces change v within the step by g dt (2.8 mm at 1/60 s
   under 10 m/s^2), which the margin covers. */
static ga2d_aabb ga2d__reach_box(const ga2d__body *b, ga2d_aabb box, ga2d_real dt)
{
    ga2d_vec d = ga2d_vec_scale(b->sim.v, dt);
    ga2d_real turn = GA2D__FABS(b->sim.w) * dt, swing = b->extent * (turn < 1 ? turn : 1);
    if (d.x < 0) box.lower.x += d.x; else box.upper.x += d.x;
    if (d.y < 0) box.lower.y += d.y; else box.upper.y += d.y;
    return ga2d__fatten(box, swing);
}

/* The radius of a shape's round part (0: sharp). */
static ga2d_real ga2d__shape_radius(const ga2d__shape *s)
{
    switch (s->geom.type) {
    case GA2D_SHAPE_CIRCLE: return s->geom.as.circle.radius;
    case GA2D_SHAPE_CAPSULE: return s->geom.as.capsule.radius;
    case GA2D_SHAPE_POLYGON: return s->geom.as.polygon.radius;
    default: return 0;
    }
}

/* A shape's AABB with its body placed by x. */
static ga2d_aabb ga2d__shape_aabb(const ga2d__shape *s, ga2d_transform x)
{
    const ga2d_geometry *g = &s->geom;
    ga2d_aabb box;
    ga2d_vec p1, p2;
    ga2d_real r = 0;
    switch (g->type) {
    case GA2D_SHAPE_POLYGON: return ga2d_polygon_aabb(&g->as.polygon, x);
    case GA2D_SHAPE_CIRCLE:
        p1 = p2 = ga2d_transform_apply(x, g->as.circle.center);
        r = g->as.circle.radius;
        break;
    case GA2D_SHAPE_CAPSULE:
        p1 = ga2d_transform_apply(x, g->as.capsule.center1);
        p2 = ga2d_transform_apply(x, g->as.capsule.center2);
        r = g->as.capsule.radius;
        break;
    default:
        p1 = ga2d_transform_apply(x, ga2d__segment_of(g)->point1);
        p2 = ga2d_transform_apply(x, ga2d__segment_of(g)->point2);
        break;
    }
    box.lower = ga2d_vec_make(p1.x < p2.x ? p1.x : p2.x, p1.y < p2.y ? p1.y : p2.y);
    box.upper = ga2d_vec_make(p1.x > p2.x ? p1.x : p2.x, p1.y > p2.y ? p1.y : p2.y);
    if (g->type == GA2D_SHAPE_CHAIN_SEGMENT) {
        /* a valley's neighbour too: the face bounds what lies over it
           (ga2d__chain_face), and a body deflected by the neighbour into
           the face within one step must already be its pair */
        const ga2d_chain_segment *cs = &g->as.chain_segment;
        ga2d__chain_joins j;
        int k;
        if (ga2d__chain_joins_of(cs, &j))
            for (k = 0; k < 2; ++k)
                if (j.valley[k]) {
                    ga2d_aabb ghost;
                    ghost.lower = ghost.upper = ga2d_transform_apply(x, k == 0 ? cs->ghost1 : cs->ghost2);
                    box = ga2d_aabb_union(box, ghost);
                }
    }
    return ga2d__fatten(box, r);
}

/* Whether a shape's fat box no longer holds all its body can reach with
   it in this step, and the box it needs then (*fat): the reach grown by
   the margin and stretched along one more step of motion, so a body
   flying steadily re-fits every other step.  A box more than four
   margins larger than that (a fast body that has slowed) is re-fitted
   too, or it would hold pairs it can no longer reach. */
static int ga2d__needs_refit(const ga2d_world *w, const ga2d__body *b, const ga2d__shape *s, ga2d_aabb *fat, ga2d_aabb *now)
{
    ga2d_aabb reach, box = ga2d__fat_box(w, s);
    ga2d_real margin = ga2d__margin(w, b);
    *now = ga2d__shape_aabb(s, ga2d__body_xf(b));
    reach = ga2d__reach_box(b, *now, w->step.dt);
    *fat = ga2d__fatten(ga2d__reach_box(b, reach, w->step.dt), margin);
    return !(ga2d_aabb_contains(box, reach) && ga2d_aabb_contains(ga2d__fatten(*fat, 4 * margin), box));
}

/* How far outer reaches past inner on its nearest side (how far inner
   can move, in any direction, and stay in it; negative: it is out) and on
   its farthest, taken into *least and *most. */
static void ga2d__box_gaps(ga2d_aabb outer, ga2d_aabb inner, ga2d_real *least, ga2d_real *most)
{
    ga2d_real a = inner.lower.x - outer.lower.x, b = inner.lower.y - outer.lower.y;
    ga2d_real c = outer.upper.x - inner.upper.x, d = outer.upper.y - inner.upper.y;
    ga2d_real lo = a < b ? a : b, hi = a > b ? a : b;
    lo = c < lo ? c : lo;
    lo = d < lo ? d : lo;
    hi = c > hi ? c : hi;
    hi = d > hi ? d : hi;
    *least = lo < *least ? lo : *least;
    *most = hi > *most ? hi : *most;
}

/* The tree takes a body's shapes' new fat boxes and they are queued for
   pair finding: then every pair the step can bring into touch exists
   before the narrowphase runs. */
static void ga2d__update_proxy(ga2d_world *w, int slot)
{
    ga2d__body *b = &w->bodies[slot];
    int s;
    b->box_slack = -1; /* moved, or its shapes or mass changed (ga2d__update_mass's
                          callers come here): found again at the next step */
    b->boxes_changed = w->box_clock;
    for (s = b->shape_head; s >= 0; s = w->shapes[s].next) {
        ga2d__shape *sh = &w->shapes[s];
        ga2d_aabb fat, now;
        if (!ga2d__needs_refit(w, b, sh, &fat, &now)) continue;
        ga2d__tree_move(ga2d__tree_of(w, sh), sh->proxy, fat);
        ga2d__buffer_move(w, s);
    }
}

/* Pair finding for one queued shape: the query callback's context.  The
   pairs it wants are looked up in the pair set a batch at a time, each
   batch's slots prefetched first: a look-up is a cache miss in a big
   world, and the batch's misses overlap rather than wait in turn. */
#define GA2D__PAIR_BATCH 32
typedef struct ga2d__pair_query {
    ga2d_world *w;
    int self;
    int count;                           /* pairs waiting in keys */
    uint64_t keys[GA2D__PAIR_BATCH];
} ga2d__pair_query;

/* The waiting pairs that have no contact join the new pairs. */
static void ga2d__pairs_flush(ga2d__pair_query *q)
{
    ga2d_world *w = q->w;
    int k;
    if (w->pair_capacity)
        for (k = 0; k < q->count; ++k) GA2D__PREFETCH_READ(&w->pair_keys[ga2d__hash(q->keys[k]) & (uint32_t)(w->pair_capacity - 1)]);
    for (k = 0; k < q->count; ++k) {
        if (ga2d__pairs_has(w, q->keys[k])) continue;
        if (!ga2d__grow(&w->mem, (void **)&w->new_pairs, &w->new_pair_capacity, w->new_pair_count + 1,
                        sizeof *w->new_pairs)) {
            w->step.error = GA2D_ERR_OUT_OF_MEMORY;
            break;
        }
        w->new_pairs[w->new_pair_count++] = q->keys[k];
    }
    q->count = 0;
}

static void ga2d__pair_found(void *ctx, int other)
{
    ga2d__pair_query *q = (ga2d__pair_query *)ctx;
    ga2d_world *w = q->w;
    int a = q->self < other ? q->self : other, b = q->self < other ? other : q->self;
    if (other == q->self) return;
    /* both queued: the one queued first (smaller slot) finds the pair */
    if (w->shapes[other].in_move && other < q->self) return;
    if (!ga2d__pair_wanted(w, a, b)) return;
    q->keys[q->count++] = ga2d__pair_key(a, b);
    if (q->count == GA2D__PAIR_BATCH) ga2d__pairs_flush(q);
}

static int ga2d__cmp_int(const void *x, const void *y) { int a = *(const int *)x, b = *(const int *)y; return (a > b) - (a < b); }
static int ga2d__cmp_u64(const void *x, const void *y)
{
    uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
    return (a > b) - (a < b);
}

/* ga2d__reuse_manifold for a pair with a round side (radii ra, rb), by
   its cores: t is B's motion in A's frame since the manifold was held,
   eps how far B's core point may have moved.  0: collide anew. */
static int ga2d__reuse_round(const ga2d_world *w, ga2d__contact *c, ga2d_transform t, ga2d_transform xa, ga2d_vec d_ab,
                             ga2d_real eps)
{
    const ga2d__held *hd = &c->held;
    const ga2d__shape *sa = &w->shapes[c->shape_a], *sb = &w->shapes[c->shape_b];
    ga2d_real ra = sa->radius, rb = sb->radius;
    ga2d_vec n = hd->normal, core_a[2], core_b[2];
    ga2d_manifold *m = &c->manifold;
    int disc_a = sa->geom.type == GA2D_SHAPE_CIRCLE, disc_b = sb->geom.type == GA2D_SHAPE_CIRCLE, k;
    /* the line the point lies on: A's core's (1), B's (2) or halfway (0) */
    int line = disc_a != disc_b ? (disc_a ? 1 : 2) : (ra == 0) != (rb == 0) ? (ra != 0 ? 1 : 2) : 0;
    if (disc_a && disc_b) return 0;
    for (k = 0; k < m->count; ++k) {
        ga2d_real half = hd->separation[k] / 2;
        ga2d_vec held_b = ga2d_vec_add(hd->point[k], ga2d_vec_scale(n, rb + half)), moved;
        core_a[k] = ga2d_vec_sub(hd->point[k], ga2d_vec_scale(n, ra + half));
        core_b[k] = ga2d_transform_apply(t, held_b);
        moved = ga2d_vec_sub(core_b[k], held_b);
        if (!(GA2D__FABS(moved.x) <= eps && GA2D__FABS(moved.y) <= eps)) return 0;
    }
    m->normal = ga2d_rotate(xa.q, n);
    for (k = 0; k < m->count; ++k) {
        ga2d_manifold_point *p = &m->points[k];
        ga2d_real sep = ga2d_dot(ga2d_vec_sub(core_b[k], core_a[k]), n) - ra - rb;
        /* midway between the surfaces, on the chosen core's line */
        ga2d_vec from_a = ga2d_vec_add(core_a[k], ga2d_vec_scale(n, ra + sep / 2));
        ga2d_vec from_b = ga2d_vec_sub(core_b[k], ga2d_vec_scale(n, rb + sep / 2));
        ga2d_vec local = line == 1 ? from_a : line == 2 ? from_b : ga2d_vec_scale(ga2d_vec_add(from_a, from_b), GA2D__R(0.5));
        p->anchor_a = ga2d_rotate(xa.q, local);
        p->anchor_b = ga2d_vec_sub(p->anchor_a, d_ab);
        p->point = ga2d_vec_add(xa.p, p->anchor_a);
        p->separation = sep;
        p->persisted = 1;
    }
    return 1;
}

/* A touching pair that has hardly moved since its manifold was made gets
   that manifold again, carried along: each point's B side moves with B
   (t: B's motion in A's frame since then), its separation grows by that
   motion along the normal, and the point stays midway.  This is how the
   solver already follows a point between substeps (ga2d__point_now), to
   first order exact while the same features touch.  It is kept while B
   has moved by at most half a slop relative to A, at the points and
   anywhere within the smaller polygon's reach of them (its extent times
   the turn): a feature the manifold lacks was farther apart than the
   speculative margin (4 slop), so it cannot have come into touch, and a
   point clipped at a face's end is off by at most that half slop along
   the face.  A resting pile then skips the separating-axis search for
   nearly every pair.  A pair with a round side is carried by its cores
   instead: the points where the normal through the point meets each
   core (A's fixed in A's frame, B's moved with B), the separation their
   distance along the normal less both radii, and the point midway between
   the surfaces, on the normal's line through one side's core: a disc's
   (its centre: exact however it turns), else the round side's, else
   halfway between the two lines.  Carried by the point itself, a stopped
   disc's point lagged its bottom as it turned, and the normal impulse's
   moment crept it forward; through its centre the point stays under it,
   as the solver keeps it within a step (ga2d__point_now).  Two discs are
   collided anew (as cheap as carried).  Returns 0 when the pair moved too
   far and must be collided anew. */
static int ga2d__reuse_manifold(const ga2d_world *w, ga2d__contact *c, const ga2d__body *a, const ga2d__body *b,
                                ga2d_transform xa, ga2d_transform xb)
{
    const ga2d__held *hd = &c->held;
    ga2d_transform t = ga2d_transform_mul(ga2d__inv_mul(xa, xb), ga2d_transform_inverse(hd->rel));
    ga2d_real eps = GA2D__R(0.5) * w->slop, reach = 2 * (a->extent < b->extent ? a->extent : b->extent);
    ga2d_vec moved[2], d_ab = ga2d_vec_sub(xb.p, xa.p);
    ga2d_manifold *m = &c->manifold;
    int k;
    if (!c->touching || !(t.q.c > 0) || !(GA2D__FABS(t.q.s) * reach <= eps)) return 0;
    if (c->extras && (w->shapes[c->shape_a].radius != 0 || w->shapes[c->shape_b].radius != 0))
        return ga2d__reuse_round(w, c, t, xa, d_ab, eps);
    for (k = 0; k < m->count; ++k) {
        moved[k] = ga2d_vec_sub(ga2d_transform_apply(t, hd->point[k]), hd->point[k]);
        if (!(GA2D__FABS(moved[k].x) <= eps && GA2D__FABS(moved[k].y) <= eps)) return 0;
    }
    m->normal = ga2d_rotate(xa.q, hd->normal);
    for (k = 0; k < m->count; ++k) {
        ga2d_manifold_point *p = &m->points[k];
        p->anchor_a = ga2d_rotate(xa.q, ga2d_vec_add(hd->point[k], ga2d_vec_scale(moved[k], GA2D__R(0.5))));
        p->anchor_b = ga2d_vec_sub(p->anchor_a, d_ab);
        p->point = ga2d_vec_add(xa.p, p->anchor_a);
        p->separation = hd->separation[k] + ga2d_dot(moved[k], hd->normal);
        p->persisted = 1;
    }
    return 1;
}

/* Keeps a new manifold in A's frame (xa: A's placement) for reuse. */
static void ga2d__hold_manifold(ga2d__held *hd, ga2d_transform xa, ga2d_transform xb, const ga2d_manifold *m)
{
    int k;
    hd->rel = ga2d__inv_mul(xa, xb);
    hd->normal = ga2d_rotate_inv(xa.q, m->normal);
    for (k = 0; k < m->count; ++k) {
        hd->point[k] = ga2d_rotate_inv(xa.q, m->points[k].anchor_a);
        hd->separation[k] = m->points[k].separation;
    }
}

/* Ends every contact of a body (it is being destroyed or refiltered). */
static void ga2d__destroy_body_contacts(ga2d_world *w, int slot, int only_unwanted)
{
    int link = ga2d__first_edge(w, slot);
    while (link >= 0) {
        int ci = link >> 1, next = ga2d__next_edge(w, link);
        if (!only_unwanted || !ga2d__pair_wanted(w, w->contacts[ci].shape_a, w->contacts[ci].shape_b)) ga2d__destroy_contact(w, ci);
        link = next;
    }
}

GA2D_API ga2d_result ga2d_body_set_filter(ga2d_world *w, ga2d_body_id id, ga2d_filter f)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    int s;
    if (r != GA2D_OK) return r;
    ga2d__wake(w, ga2d__slot(id));
    for (s = b->shape_head; s >= 0; s = w->shapes[s].next) {
        w->shapes[s].filter = f;
        ga2d__tree_set_category(ga2d__tree_of(w, &w->shapes[s]), w->shapes[s].proxy, f.category_bits);
    }
    ga2d__destroy_body_contacts(w, ga2d__slot(id), 1);
    ga2d__buffer_body(w, ga2d__slot(id)); /* pairs it may now make */
    return GA2D_OK;
}

GA2D_API ga2d_filter ga2d_body_filter(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    ga2d_filter f;
    memset(&f, 0, sizeof f);
    return b && b->shape_head >= 0 ? w->shapes[b->shape_head].filter : f;
}

GA2D_API ga2d_aabb ga2d_body_fat_aabb(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    ga2d_aabb box;
    int s;
    memset(&box, 0, sizeof box);
    if (!b) return box;
    if (b->shape_head < 0) {
        box.lower = box.upper = ga2d__body_origin(b);
        return box;
    }
    box = ga2d__fat_box(w, &w->shapes[b->shape_head]);
    for (s = w->shapes[b->shape_head].next; s >= 0; s = w->shapes[s].next) box = ga2d_aabb_union(box, ga2d__fat_box(w, &w->shapes[s]));
    return box;
}

static int ga2d__list_contacts(const ga2d_world *w, ga2d_contact_data *out, int capacity, int touching_only)
{
    int ci, n = 0;
    if (!w) return 0;
    for (ci = 0; ci < w->contact_used; ++ci) {
        const ga2d__contact *c = &w->contacts[ci];
        if (c->next_free != -2 || (touching_only && !c->touching)) continue;
        if (out && n < capacity) ga2d__contact_data(w, c, &out[n]);
        ++n;
    }
    return n;
}

GA2D_API int ga2d_world_get_pairs(const ga2d_world *w, ga2d_contact_data *out, int capacity)
{
    return ga2d__list_contacts(w, out, capacity, 0);
}

GA2D_API int ga2d_world_get_contacts(const ga2d_world *w, ga2d_contact_data *out, int capacity)
{
    return ga2d__list_contacts(w, out, capacity, 1);
}

GA2D_API ga2d_contact_events ga2d_world_contact_events(const ga2d_world *w)
{
    ga2d_contact_events e;
    memset(&e, 0, sizeof e);
    if (!w) return e;
    e.begin = w->begin_events;
    e.begin_count = w->begin_count;
    e.end = w->end_events;
    e.end_count = w->end_count;
    e.hit = w->hit_events;
    e.hit_count = w->hit_count;
    return e;
}

GA2D_API int ga2d_body_get_contacts(const ga2d_world *w, ga2d_body_id id, ga2d_contact_data *out, int capacity)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    int link, n = 0, k;
    if (!b) return 0;
    for (link = ga2d__first_edge(w, ga2d__slot(id)); link >= 0; link = ga2d__next_edge(w, link)) {
        const ga2d__contact *c = &w->contacts[link >> 1];
        if (!c->touching) continue;
        if (out && n < capacity) {
            ga2d_contact_data *d = &out[n];
            ga2d__contact_data(w, c, d);
            if (link & 1) { /* the body is B: the contact turned round */
                ga2d_body_id tb = d->body_a;
                ga2d_shape_id ts = d->shape_a;
                d->body_a = d->body_b;
                d->body_b = tb;
                d->shape_a = d->shape_b;
                d->shape_b = ts;
                d->manifold.normal = ga2d_vec_neg(d->manifold.normal);
                for (k = 0; k < d->manifold.count; ++k) {
                    ga2d_vec ta = d->manifold.points[k].anchor_a;
                    d->manifold.points[k].anchor_a = d->manifold.points[k].anchor_b;
                    d->manifold.points[k].anchor_b = ta;
                }
            }
        }
        ++n;
    }
    return n;
}

/* ---------------------------------------------------------------- world */
GA2D_API ga2d_world_def ga2d_default_world_def(void)
{
    ga2d_world_def d;
    memset(&d, 0, sizeof d);
    d.gravity = ga2d_vec_make(0, GA2D__R(GA2D_DEFAULT_GRAVITY));
    d.substeps = GA2D_DEFAULT_SUBSTEPS;
    d.integrator = GA2D_INTEGRATOR_SYMPLECTIC_EULER;
    d.rotation_update = GA2D_ROTATION_EXACT;
    d.length_units_per_meter = 1;
    d.solver = GA2D_SOLVER_SOFT_STEP;
    d.velocity_iterations = GA2D_DEFAULT_VELOCITY_ITERATIONS;
    d.position_iterations = GA2D_DEFAULT_POSITION_ITERATIONS;
    d.contact_hertz = GA2D__R(GA2D_DEFAULT_CONTACT_HERTZ);
    d.contact_damping_ratio = GA2D__R(GA2D_DEFAULT_CONTACT_DAMPING_RATIO);
    d.contact_push_max_velocity = GA2D__R(GA2D_DEFAULT_CONTACT_PUSH_MAX_VELOCITY);
    d.restitution_threshold = GA2D__R(GA2D_DEFAULT_RESTITUTION_THRESHOLD);
    d.hit_event_threshold = GA2D__R(GA2D_DEFAULT_HIT_EVENT_THRESHOLD);
    d.enable_sleep = 1;
    d.enable_warm_starting = 1;
    d.enable_friction = 1;
    d.enable_restitution = 1;
    d.enable_continuous = 1;
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

static int ga2d__is_zero(const void *p, size_t n)
{
    const unsigned char *c = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; ++i)
        if (c[i]) return 0;
    return 1;
}

/* Field f of a resolved def: taken from `in` where the def was stamped by
   its default function or the field is not zero, else the default.  Set
   field by field into zeroed memory, so that the padding is zero too (a
   world's def is saved in snapshots). */
#define GA2D__TAKE(f) (out->f = (stamped || !ga2d__is_zero(&in->f, sizeof in->f)) ? in->f : dflt.f)
/* ... and a field whose zero means the default in every def */
#define GA2D__TAKE_NONZERO(f) (out->f = in->f != 0 ? in->f : dflt.f)

/* The one place a world def's zeros become defaults (see "Defs"). */
static void ga2d__resolve_world_def(const ga2d_world_def *in, ga2d_world_def *out)
{
    ga2d_world_def dflt = ga2d_default_world_def();
    int stamped = in->internal_cookie == GA2D_DEF_COOKIE;
    memset(out, 0, sizeof *out);
    out->internal_cookie = GA2D_DEF_COOKIE;
    GA2D__TAKE(gravity);
    GA2D__TAKE_NONZERO(substeps);
    GA2D__TAKE(integrator);
    GA2D__TAKE(rotation_update);
    GA2D__TAKE_NONZERO(length_units_per_meter);
    GA2D__TAKE(allocator);
    GA2D__TAKE(force_callback);
    GA2D__TAKE(force_context);
    GA2D__TAKE(solver);
    GA2D__TAKE_NONZERO(velocity_iterations);
    GA2D__TAKE_NONZERO(position_iterations);
    GA2D__TAKE_NONZERO(contact_hertz);
    GA2D__TAKE_NONZERO(contact_damping_ratio);
    GA2D__TAKE_NONZERO(contact_push_max_velocity);
    GA2D__TAKE_NONZERO(restitution_threshold);
    GA2D__TAKE(enable_sleep);
    GA2D__TAKE(enable_warm_starting);
    GA2D__TAKE(enable_friction);
    GA2D__TAKE(enable_restitution);
    GA2D__TAKE(pre_solve);
    GA2D__TAKE(pre_solve_context);
    GA2D__TAKE_NONZERO(hit_event_threshold);
    GA2D__TAKE(enable_continuous);
    GA2D__TAKE(worker_count);
    GA2D__TAKE(enqueue_task);
    GA2D__TAKE(finish_task);
    GA2D__TAKE(user_task_context);
}

/* |v| s, with |v| taken after scaling by the larger component: finite
   whenever the product is, also where |v| alone would overflow. */
static ga2d_real ga2d__length_times(ga2d_vec v, ga2d_real s)
{
    ga2d_real ax = GA2D__FABS(v.x), ay = GA2D__FABS(v.y), m = ax > ay ? ax : ay;
    if (m == 0) return 0;
    return (m * s) * GA2D__SQRT((v.x / m) * (v.x / m) + (v.y / m) * (v.y / m));
}

/* |g| within GA2D_MAX_GRAVITY (in the world's length units) */
static int ga2d__gravity_ok(ga2d_vec g, ga2d_real units)
{
    return ga2d__length_times(g, 1) <= GA2D__R(GA2D_MAX_GRAVITY) * units;
}


/* A resolved def's values against their bounds. */
static ga2d_result ga2d__world_def_check(const ga2d_world_def *d)
{
    if (!ga2d__finite_vec(d->gravity) || !ga2d__finite(d->length_units_per_meter)) return GA2D_ERR_NOT_FINITE;
    if (d->substeps < 0 || d->substeps > GA2D_MAX_SUBSTEPS) return GA2D_ERR_INVALID_ARGUMENT;
    if ((int)d->integrator < 0 || (int)d->integrator >= GA2D_INTEGRATOR_COUNT) return GA2D_ERR_INVALID_ARGUMENT;
    if ((int)d->rotation_update < 0 || (int)d->rotation_update >= GA2D_ROTATION_COUNT) return GA2D_ERR_INVALID_ARGUMENT;
    if (d->length_units_per_meter < 0) return GA2D_ERR_INVALID_ARGUMENT;
    if (!ga2d__gravity_ok(d->gravity, d->length_units_per_meter > 0 ? d->length_units_per_meter : 1))
        return GA2D_ERR_TOO_LARGE;
    if (!ga2d__finite(d->contact_hertz) || !ga2d__finite(d->contact_damping_ratio) ||
        !ga2d__finite(d->contact_push_max_velocity) || !ga2d__finite(d->restitution_threshold) ||
        !ga2d__finite(d->hit_event_threshold))
        return GA2D_ERR_NOT_FINITE;
    if ((int)d->solver < 0 || (int)d->solver >= GA2D_SOLVER_COUNT || d->velocity_iterations < 0 ||
        d->velocity_iterations > GA2D_MAX_SUBSTEPS || d->position_iterations < 0 || d->position_iterations > GA2D_MAX_SUBSTEPS ||
        d->contact_hertz < 0 || d->contact_damping_ratio < 0 || d->contact_push_max_velocity < 0 ||
        d->restitution_threshold < 0 || d->hit_event_threshold < 0)
        return GA2D_ERR_INVALID_ARGUMENT;
    if ((d->allocator.alloc == NULL) != (d->allocator.free == NULL)) return GA2D_ERR_INVALID_ARGUMENT;
    if (d->worker_count < 0 || d->worker_count > GA2D_MAX_WORKERS || (d->enqueue_task == NULL) != (d->finish_task == NULL))
        return GA2D_ERR_INVALID_ARGUMENT;
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_def_validate(const ga2d_world_def *def)
{
    ga2d_world_def d;
    if (!def) return GA2D_ERR_INVALID_ARGUMENT;
    ga2d__resolve_world_def(def, &d);
    return ga2d__world_def_check(&d);
}

GA2D_API ga2d_world *ga2d_world_create(const ga2d_world_def *def)
{
    ga2d_world_def d, dflt = ga2d_default_world_def();
    ga2d_world *w;
    ga2d__resolve_world_def(def ? def : &dflt, &d);
    if (ga2d__world_def_check(&d) != GA2D_OK) return NULL;
    w = (ga2d_world *)ga2d__alloc(&d.allocator, sizeof *w);
    if (!w) return NULL;
    memset(w, 0, sizeof *w);
    memcpy(&w->def, &d, sizeof d); /* its zero padding too */
    w->mem.alloc = ga2d__hook_alloc;
    w->mem.free = ga2d__hook_free;
    w->mem.ctx = w;
    w->tag = ga2d__world_tag(w);
    w->free_head = -1;
    w->shape_free = -1;
    w->chain_free = -1;
    w->joint_free = -1;
    w->trees[0].root = w->trees[0].free_list = -1;
    w->trees[1].root = w->trees[1].free_list = -1;
    w->contact_free = -1;
    w->box_clock = 1; /* after every contact's boxes_checked of 0 */
    w->step.world = w;
    w->error_slot = -1;
    w->slop = GA2D__R(GA2D_LINEAR_SLOP) * d.length_units_per_meter;
    w->speculative = GA2D__R(GA2D_SPECULATIVE_DISTANCE) * d.length_units_per_meter;
    w->aabb_margin = GA2D__R(GA2D_AABB_MARGIN) * d.length_units_per_meter;
    w->step.dt = GA2D__R(1.0 / 60);
    return w;
}

/* Frees everything.  The arrays are taken out of the world first, so a
   free hook that reads the world finds it empty (and locked), never freed
   memory. */
static void ga2d__destroy_now(ga2d_world *w)
{
    ga2d_world dead = *w;
    ga2d_allocator user = w->def.allocator, *a = &w->mem;
    memset(w, 0, sizeof *w);
    w->def = dead.def;
    w->mem = dead.mem;
    w->free_head = w->contact_free = w->error_slot = w->joint_free = -1;
    w->trees[0].root = w->trees[0].free_list = w->trees[1].root = w->trees[1].free_list = -1;
    w->lock = GA2D__LOCK_DEAD;
    w->depth = 1; /* a destroy from a free hook changes nothing */
    w->destroy_pending = 1;
    w = &dead;
    GA2D__FREE_ARRAY(a, w->bodies, w->body_capacity);
    {
        int k;
        for (k = 0; k < w->shape_used; ++k) GA2D__FREE_ARRAY(a, w->shapes[k].visitors, w->shapes[k].visitor_capacity);
    }
    GA2D__FREE_ARRAY(a, w->shapes, w->shape_capacity);
    {
        int k;
        for (k = 0; k < w->chain_used; ++k) GA2D__FREE_ARRAY(a, w->chains[k].shapes, w->chains[k].count);
    }
    GA2D__FREE_ARRAY(a, w->chains, w->chain_capacity);
    GA2D__FREE_ARRAY(a, w->joints, w->joint_capacity);
    GA2D__FREE_ARRAY(a, w->sensor_begin, w->sensor_begin_capacity);
    GA2D__FREE_ARRAY(a, w->hit_events, w->hit_capacity);
    GA2D__FREE_ARRAY(a, w->sensor_end, w->sensor_end_capacity);
    GA2D__FREE_ARRAY(a, w->sensor_scratch, w->sensor_scratch_capacity);
    GA2D__FREE_ARRAY(a, w->moving, w->moving_capacity);
    ga2d__tree_release(a, &w->trees[0]);
    ga2d__tree_release(a, &w->trees[1]);
    GA2D__FREE_ARRAY(a, w->move_buf, w->move_capacity);
    GA2D__FREE_ARRAY(a, w->new_pairs, w->new_pair_capacity);
    GA2D__FREE_ARRAY(a, w->contacts, w->contact_capacity);
    GA2D__FREE_ARRAY(a, w->touches, w->touch_capacity);
    GA2D__FREE_ARRAY(a, w->touches_next, w->touch_next_capacity);
    GA2D__FREE_ARRAY(a, w->began, w->began_capacity);
    GA2D__FREE_ARRAY(a, w->pair_keys, w->pair_capacity);
    GA2D__FREE_ARRAY(a, w->begin_events, w->begin_capacity);
    GA2D__FREE_ARRAY(a, w->end_events, w->end_capacity);
    ga2d__step_free(a, &w->step);
    GA2D__FREE_ARRAY(a, w->wake_queue, w->wake_capacity);
    ga2d__free(&user, a->ctx, sizeof *w);
}

/* From user code that the library runs (a callback, an allocator hook)
   the world goes when that library call returns: the call finishes
   without calling back again, then frees the world. */
GA2D_API void ga2d_world_destroy(ga2d_world *w)
{
    if (!w) return;
    if (w->depth > 0) {
        w->destroy_pending = 1;
        return;
    }
    ga2d__destroy_now(w);
}

GA2D_API ga2d_body_id ga2d_world_error_body(const ga2d_world *w)
{
    ga2d_body_id id = ga2d_body_id_null();
    if (!w || w->error_slot < 0 || w->error_slot >= w->body_used || w->bodies[w->error_slot].type < 0) return id;
    return ga2d__id_of(w, w->error_slot);
}

GA2D_API double ga2d_world_time(const ga2d_world *w)
{
    if (!w) return 0;
    return (w->lock & GA2D__LOCK_FIELD) ? w->eval_time : w->time;
}

GA2D_API ga2d_world_counters ga2d_world_get_counters(const ga2d_world *w)
{
    ga2d_world_counters c;
    memset(&c, 0, sizeof c);
    if (!w) return c;
    c = w->counters;
    c.body_count = w->body_count;
    c.shape_count = w->shape_count;
    c.joint_count = w->joint_count;
    c.moving_body_count = w->moving_count;
    c.pair_count = w->contact_count;
    c.touching_count = w->touching_count;
    c.awake_body_count = w->moving_dynamic;
    return c;
}

GA2D_API ga2d_vec ga2d_world_gravity(const ga2d_world *w) { return w ? w->def.gravity : ga2d_vec_make(0, 0); }

/* within GA2D_MAX_COORDINATE, as a polygon's vertices are */
static int ga2d__coordinate_ok(ga2d_vec p)
{
    return GA2D__FABS(p.x) <= GA2D__R(GA2D_MAX_COORDINATE) && GA2D__FABS(p.y) <= GA2D__R(GA2D_MAX_COORDINATE);
}

GA2D_API ga2d_result ga2d_world_set_gravity(ga2d_world *w, ga2d_vec g)
{
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    if (!ga2d__finite_vec(g)) return GA2D_ERR_NOT_FINITE;
    if (!ga2d__gravity_ok(g, w->def.length_units_per_meter)) return GA2D_ERR_TOO_LARGE;
    w->def.gravity = g;
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_set_substeps(ga2d_world *w, int substeps)
{
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    if (substeps < 1 || substeps > GA2D_MAX_SUBSTEPS) return GA2D_ERR_INVALID_ARGUMENT;
    w->def.substeps = substeps;
    return GA2D_OK;
}

/* Forget the force field's last evaluation: its forces and Verlet's cached
   accelerations (so the next Verlet substep evaluates afresh). */
static void ga2d__reset_field(ga2d_world *w)
{
    int k;
    for (k = 0; k < w->moving_count; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        b->sim.field_force = b->sim.field_accel = ga2d_vec_make(0, 0);
        b->sim.field_torque = b->sim.field_alpha = 0;
        b->sim.field_valid = 0;
    }
}

/* Checks a world and an enum value in [0, count) before a setter writes. */
static ga2d_result ga2d__check_mode(const ga2d_world *w, int value, int count)
{
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    return value < 0 || value >= count ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_set_integrator(ga2d_world *w, ga2d_integrator integrator)
{
    ga2d_result r = ga2d__check_mode(w, (int)integrator, GA2D_INTEGRATOR_COUNT);
    if (r != GA2D_OK) return r;
    if (integrator == GA2D_INTEGRATOR_RK4) {
        int ok;
        ga2d__enter(w);
        ok = ga2d__reserve_rk4(w, w->moving_capacity);
        /* the world may have been destroyed from the allocator: it is
           still here until the leave, and it is not touched after it */
        if (!ok || w->destroy_pending) {
            ga2d__leave(w);
            return ok ? GA2D_OK : GA2D_ERR_OUT_OF_MEMORY;
        }
        ga2d__leave(w);
    }
    w->def.integrator = integrator;
    ga2d__reset_field(w); /* other integrators moved bodies without it */
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_set_rotation_update(ga2d_world *w, ga2d_rotation_update mode)
{
    ga2d_result r = ga2d__check_mode(w, (int)mode, GA2D_ROTATION_COUNT);
    if (r == GA2D_OK) w->def.rotation_update = mode;
    return r;
}

GA2D_API ga2d_result ga2d_world_set_solver(ga2d_world *w, ga2d_solver solver)
{
    ga2d_result r = ga2d__check_mode(w, (int)solver, GA2D_SOLVER_COUNT);
    if (r == GA2D_OK) w->def.solver = solver;
    return r;
}

/* A world switch: refused while the world steps. */
static ga2d_result ga2d__set_switch(ga2d_world *w, int *field, int on)
{
    if (w->lock) return GA2D_ERR_LOCKED;
    *field = on != 0;
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_enable_sleep(ga2d_world *w, int on)
{
    int s;
    ga2d_result r = w ? ga2d__set_switch(w, &w->def.enable_sleep, on) : GA2D_ERR_INVALID_ARGUMENT;
    if (r != GA2D_OK) return r;
    if (!on)
        for (s = 0; s < w->body_used; ++s)
            if (w->bodies[s].type == GA2D_BODY_DYNAMIC && !w->bodies[s].awake) ga2d__wake(w, s);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_enable_warm_starting(ga2d_world *w, int on)
{
    return w ? ga2d__set_switch(w, &w->def.enable_warm_starting, on) : GA2D_ERR_INVALID_ARGUMENT;
}

GA2D_API ga2d_result ga2d_world_enable_friction(ga2d_world *w, int on)
{
    return w ? ga2d__set_switch(w, &w->def.enable_friction, on) : GA2D_ERR_INVALID_ARGUMENT;
}

GA2D_API ga2d_result ga2d_world_enable_continuous(ga2d_world *w, int on)
{
    return w ? ga2d__set_switch(w, &w->def.enable_continuous, on) : GA2D_ERR_INVALID_ARGUMENT;
}

GA2D_API ga2d_result ga2d_world_enable_restitution(ga2d_world *w, int on)
{
    return w ? ga2d__set_switch(w, &w->def.enable_restitution, on) : GA2D_ERR_INVALID_ARGUMENT;
}

GA2D_API ga2d_world_def ga2d_accurate_world_def(void)
{
    ga2d_world_def d = ga2d_default_world_def();
    d.substeps = 8;
    d.contact_hertz = 90;
    return d;
}

GA2D_API ga2d_result ga2d_world_set_force_callback(ga2d_world *w, ga2d_force_fn *fn, void *context)
{
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    w->def.force_callback = fn;
    w->def.force_context = context;
    ga2d__reset_field(w);
    return GA2D_OK;
}

/* ----------------------------------------------------- definitions checked */
/* A polygon rebuilt from its vertices, as ga2d_polygon_make checks them
   (a hand-filled struct could be anything), with its radius: finite, not
   negative, within GA2D_MAX_COORDINATE. */
static ga2d_result ga2d__polygon_remake(const ga2d_polygon *in, ga2d_polygon *out)
{
    ga2d_result r;
    if (in->count < 0 || in->count > GA2D_MAX_POLYGON_VERTICES)
        return in->count < 0 ? GA2D_ERR_INVALID_ARGUMENT : GA2D_ERR_TOO_MANY_POINTS;
    r = ga2d_polygon_make(in->vertices, in->count, out);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(in->radius)) return GA2D_ERR_NOT_FINITE;
    if (in->radius < 0) return GA2D_ERR_INVALID_ARGUMENT;
    if (in->radius > GA2D_MAX_COORDINATE) return GA2D_ERR_TOO_LARGE;
    out->radius = in->radius;
    return GA2D_OK;
}

/* A point a shape may have: finite (NOT_FINITE), within
   GA2D_MAX_COORDINATE (TOO_LARGE); 0 when fine. */
static ga2d_result ga2d__point_check(ga2d_vec p)
{
    if (!ga2d__finite_vec(p)) return GA2D_ERR_NOT_FINITE;
    if (!(GA2D__FABS(p.x) <= GA2D__R(GA2D_MAX_COORDINATE) && GA2D__FABS(p.y) <= GA2D__R(GA2D_MAX_COORDINATE)))
        return GA2D_ERR_TOO_LARGE;
    return GA2D_OK;
}

/* A radius a shape may have: finite, not negative, not beyond
   GA2D_MAX_COORDINATE. */
static ga2d_result ga2d__radius_check(ga2d_real r)
{
    if (!ga2d__finite(r)) return GA2D_ERR_NOT_FINITE;
    if (r < 0) return GA2D_ERR_INVALID_ARGUMENT;
    return r > GA2D__R(GA2D_MAX_COORDINATE) ? GA2D_ERR_TOO_LARGE : GA2D_OK;
}

/* Two ends that make a direction: apart by more than 64 eps of their
   size (closer, the capsule is a circle and the segment nothing). */
static int ga2d__ends_apart(ga2d_vec p1, ga2d_vec p2)
{
    ga2d_real size = GA2D__FABS(p1.x) + GA2D__FABS(p1.y) + GA2D__FABS(p2.x) + GA2D__FABS(p2.y);
    return ga2d_vec_length(ga2d_vec_sub(p2, p1)) > 64 * GA2D__EPS * size && ga2d_vec_normalize(ga2d_vec_sub(p2, p1), NULL) != 0;
}

/* How far out a chain's ghost may lie, per axis: a made-up one is an end
   (within M) less twice its segment turned (within 2 M per axis), and
   rounding never passes the bound, 5 M being exact in ga2d_real. */
#define GA2D__GHOST_BOUND (5 * GA2D__R(GA2D_MAX_COORDINATE))

/* A ghost beside its end: finite, within GA2D__GHOST_BOUND, and apart
   from the end so that the two make a direction. */
static ga2d_result ga2d__ghost_check(ga2d_vec ghost, ga2d_vec end)
{
    if (!ga2d__finite_vec(ghost)) return GA2D_ERR_NOT_FINITE;
    if (!(GA2D__FABS(ghost.x) <= GA2D__GHOST_BOUND && GA2D__FABS(ghost.y) <= GA2D__GHOST_BOUND)) return GA2D_ERR_TOO_LARGE;
    return ga2d__ends_apart(ghost, end) ? GA2D_OK : GA2D_ERR_REPEATED_POINTS;
}

/* A shape's geometry and density on a body of the given type, checked
   into *out (a polygon rebuilt from its vertices, as ga2d_polygon_make
   would make it).  A dynamic body's shape of positive density must have a
   mass and an inertia whose inverses are finite: the step divides by
   both. */
static ga2d_result ga2d__geometry_check(const ga2d_geometry *g, int body_type, ga2d_real density, ga2d_geometry *out)
{
    ga2d_geometry c;
    ga2d_mass m;
    ga2d_result r;
    memset(&c, 0, sizeof c);
    c.type = g->type;
    switch (g->type) {
    case GA2D_SHAPE_POLYGON:
        r = ga2d__polygon_remake(&g->as.polygon, &c.as.polygon);
        if (r == GA2D_OK) r = ga2d_polygon_mass_checked(&c.as.polygon, density, &m);
        break;
    case GA2D_SHAPE_CIRCLE:
        c.as.circle = g->as.circle;
        if ((r = ga2d__point_check(c.as.circle.center)) == GA2D_OK && (r = ga2d__radius_check(c.as.circle.radius)) == GA2D_OK)
            r = ga2d_circle_mass_checked(&c.as.circle, density, &m);
        break;
    case GA2D_SHAPE_CAPSULE:
        c.as.capsule = g->as.capsule;
        if ((r = ga2d__point_check(c.as.capsule.center1)) == GA2D_OK && (r = ga2d__point_check(c.as.capsule.center2)) == GA2D_OK &&
            (r = ga2d__radius_check(c.as.capsule.radius)) == GA2D_OK) {
            r = ga2d__ends_apart(c.as.capsule.center1, c.as.capsule.center2) ? GA2D_OK : GA2D_ERR_DEGENERATE;
            if (r == GA2D_OK) r = ga2d_capsule_mass_checked(&c.as.capsule, density, &m);
        }
        break;
    case GA2D_SHAPE_SEGMENT:
        c.as.segment = g->as.segment;
        if ((r = ga2d__point_check(c.as.segment.point1)) == GA2D_OK && (r = ga2d__point_check(c.as.segment.point2)) == GA2D_OK)
            r = body_type == GA2D_BODY_DYNAMIC ? GA2D_ERR_INVALID_ARGUMENT
                : ga2d__ends_apart(c.as.segment.point1, c.as.segment.point2) ? GA2D_OK : GA2D_ERR_DEGENERATE;
        memset(&m, 0, sizeof m);
        break;
    case GA2D_SHAPE_CHAIN_SEGMENT: {
        const ga2d_chain_segment *cs = &g->as.chain_segment;
        c.as.chain_segment = *cs;
        if ((r = ga2d__point_check(cs->segment.point1)) == GA2D_OK && (r = ga2d__point_check(cs->segment.point2)) == GA2D_OK &&
            (r = ga2d__ghost_check(cs->ghost1, cs->segment.point1)) == GA2D_OK &&
            (r = ga2d__ghost_check(cs->ghost2, cs->segment.point2)) == GA2D_OK)
            r = body_type == GA2D_BODY_DYNAMIC ? GA2D_ERR_INVALID_ARGUMENT
                : ga2d__ends_apart(cs->segment.point1, cs->segment.point2) ? GA2D_OK : GA2D_ERR_REPEATED_POINTS;
        memset(&m, 0, sizeof m);
        break;
    }
    default: return GA2D_ERR_INVALID_ARGUMENT;
    }
    if (r != GA2D_OK) return r;
    if (body_type == GA2D_BODY_DYNAMIC && density > 0 &&
        (!(m.mass > 0) || !(m.inertia > 0) || !ga2d__finite(1 / m.mass) || !ga2d__finite(1 / m.inertia)))
        return GA2D_ERR_DEGENERATE;
    *out = c;
    return GA2D_OK;
}

/* A resolved def's values against their bounds. */
static ga2d_result ga2d__body_def_check(const ga2d_body_def *d)
{
    ga2d_geometry g;
    if ((int)d->type < 0 || (int)d->type >= GA2D_BODY_TYPE_COUNT) return GA2D_ERR_INVALID_ARGUMENT;
    if (!(d->rotor.c == 0 && d->rotor.s == 0) && ga2d__finite(d->rotor.c) && ga2d__finite(d->rotor.s) &&
        ga2d_vec_normalize(ga2d_vec_make(d->rotor.c, d->rotor.s), NULL) == 0)
        return GA2D_ERR_INVALID_ARGUMENT; /* nonzero, yet too small to give a direction */
    if (!ga2d__finite_vec(d->position) || !ga2d__finite(d->rotor.c) || !ga2d__finite(d->rotor.s) ||
        !ga2d__finite_vec(d->velocity) || !ga2d__finite(d->angular_velocity) || !ga2d__finite(d->density) ||
        !ga2d__finite(d->friction) || !ga2d__finite(d->restitution) || !ga2d__finite(d->linear_damping) ||
        !ga2d__finite(d->angular_damping) || !ga2d__finite(d->gravity_scale))
        return GA2D_ERR_NOT_FINITE;
    if (!ga2d__coordinate_ok(d->position)) return GA2D_ERR_TOO_LARGE;
    if (d->type == GA2D_BODY_DYNAMIC && !(d->density > 0)) return GA2D_ERR_INVALID_ARGUMENT;
    if (d->density < 0 || d->friction < 0 || d->restitution < 0 || d->linear_damping < 0 || d->angular_damping < 0)
        return GA2D_ERR_INVALID_ARGUMENT;
    if (d->polygon.count == 0) return GA2D_OK; /* no shape */
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_POLYGON;
    g.as.polygon = d->polygon;
    return ga2d__geometry_check(&g, (int)d->type, d->density, &g);
}

/* ---------------------------------------------------------------- sensors */
/* Appends a sensor event; on failure the step (or the next one, for a
   destruction) reports OUT_OF_MEMORY. */
static int ga2d__push_sensor_event(ga2d_world *w, int end, ga2d_shape_id sensor, ga2d_shape_id visitor)
{
    ga2d_sensor_event **arr = end ? &w->sensor_end : &w->sensor_begin;
    int *count = end ? &w->sensor_end_count : &w->sensor_begin_count;
    int *cap = end ? &w->sensor_end_capacity : &w->sensor_begin_capacity;
    if (!ga2d__grow(&w->mem, (void **)arr, cap, *count + 1, sizeof **arr)) {
        w->step.error = GA2D_ERR_OUT_OF_MEMORY;
        return 0;
    }
    (*arr)[*count].sensor = sensor;
    (*arr)[*count].visitor = visitor;
    ++*count;
    return 1;
}

/* An end from a destruction waits for the next step's events; one that
   found no room makes that step report OUT_OF_MEMORY. */
static void ga2d__push_sensor_end_pending(ga2d_world *w, ga2d_shape_id sensor, ga2d_shape_id visitor)
{
    if (ga2d__push_sensor_event(w, 1, sensor, visitor)) ++w->sensor_end_pending;
    else w->sensor_end_lost = 1;
}

/* A shape about to go: a sensor ends its overlaps, a visitor leaves every
   sensor that holds it; the ends wait for the next step's events. */
static void ga2d__sensor_forget(ga2d_world *w, int k)
{
    ga2d__shape *sh = &w->shapes[k];
    int i, j;
    if (w->sensor_count == 0) return;
    ga2d__enter(w);
    if (sh->is_sensor) {
        for (i = 0; i < sh->visitor_count; ++i) {
            ga2d__push_sensor_end_pending(w, ga2d__shape_id_of(w, k), ga2d__shape_id_of(w, sh->visitors[i]));
        }
        GA2D__FREE_ARRAY(&w->mem, sh->visitors, sh->visitor_capacity);
        sh->visitors = NULL;
        sh->visitor_count = sh->visitor_capacity = 0;
        --w->sensor_count;
    } else {
        for (i = 0; i < w->shape_used; ++i) {
            ga2d__shape *se = &w->shapes[i];
            if (se->type < 0 || !se->is_sensor) continue;
            for (j = 0; j < se->visitor_count && se->visitors[j] != k; ++j) continue;
            if (j == se->visitor_count) continue;
            ga2d__push_sensor_end_pending(w, ga2d__shape_id_of(w, i), ga2d__shape_id_of(w, k));
            memmove(&se->visitors[j], &se->visitors[j + 1], (size_t)(se->visitor_count - j - 1) * sizeof *se->visitors);
            --se->visitor_count;
        }
    }
    ga2d__leave(w);
}

/* Collects a sensor's candidates (the tree query's callback). */
static void ga2d__sensor_found(void *ctx, int other)
{
    ga2d_world *w = (ga2d_world *)ctx;
    if (!ga2d__grow(&w->mem, (void **)&w->sensor_scratch, &w->sensor_scratch_capacity, w->sensor_scratch_count + 1,
                    sizeof *w->sensor_scratch)) {
        w->step.error = GA2D_ERR_OUT_OF_MEMORY;
        return;
    }
    w->sensor_scratch[w->sensor_scratch_count++] = other;
}

/* Whether a visitor overlaps a sensor now (touching counts). */
static int ga2d__sensor_sees(const ga2d_world *w, const ga2d__shape *se, int v)
{
    const ga2d__shape *vi = &w->shapes[v];
    ga2d_manifold m;
    if (vi->type < 0 || vi->is_sensor || !vi->sensor_events || vi->body == se->body || !ga2d_should_collide(se->filter, vi->filter))
        return 0;
    return ga2d__collide_geometries(&se->geom, ga2d__body_xf(&w->bodies[se->body]), &vi->geom,
                                    ga2d__body_xf(&w->bodies[vi->body]), w->slop, 0, &m) > 0;
}

/* Book-keeping after the step: each sensor, in slot order, finds what
   overlaps its shape now (a query of both trees with its own box, then an
   exact test), and the changes against what it held are its events. */
static void ga2d__update_sensors(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int k, i, j, n;
    for (k = 0; k < w->shape_used && w->sensor_count > 0; ++k) {
        ga2d__shape *se = &w->shapes[k];
        ga2d_aabb box;
        if (se->type < 0 || !se->is_sensor) continue;
        box = ga2d__shape_aabb(se, ga2d__body_xf(&w->bodies[se->body]));
        w->sensor_scratch_count = 0;
        ga2d__tree_query(&w->trees[0], box, GA2D__ALL_CATEGORIES, ga2d__sensor_found, w);
        ga2d__tree_query(&w->trees[1], box, GA2D__ALL_CATEGORIES, ga2d__sensor_found, w);
        if (c->error == GA2D_ERR_OUT_OF_MEMORY) return;
        for (i = 0, n = 0; i < w->sensor_scratch_count; ++i)
            if (ga2d__sensor_sees(w, se, w->sensor_scratch[i])) w->sensor_scratch[n++] = w->sensor_scratch[i];
        w->counters.sensor_tests += w->sensor_scratch_count;
        if (n > 1) qsort(w->sensor_scratch, (size_t)n, sizeof *w->sensor_scratch, ga2d__cmp_int);
        if (!ga2d__grow(&w->mem, (void **)&se->visitors, &se->visitor_capacity, n, sizeof *se->visitors)) {
            c->error = GA2D_ERR_OUT_OF_MEMORY;
            return;
        }
        /* the two ascending lists, merged: what is only new began, what is only old ended */
        for (i = 0, j = 0; i < n || j < se->visitor_count;) {
            int now = i < n ? w->sensor_scratch[i] : -1, was = j < se->visitor_count ? se->visitors[j] : -1;
            if (was < 0 || (now >= 0 && now < was)) {
                ga2d__push_sensor_event(w, 0, ga2d__shape_id_of(w, k), ga2d__shape_id_of(w, now));
                ++i;
            } else if (now < 0 || was < now) {
                ga2d__push_sensor_event(w, 1, ga2d__shape_id_of(w, k), ga2d__shape_id_of(w, was));
                ++j;
            } else {
                ++i;
                ++j;
            }
        }
        if (n > 0) memcpy(se->visitors, w->sensor_scratch, (size_t)n * sizeof *se->visitors);
        se->visitor_count = n;
    }
}

GA2D_API ga2d_sensor_events ga2d_world_sensor_events(const ga2d_world *w)
{
    ga2d_sensor_events e;
    memset(&e, 0, sizeof e);
    if (!w) return e;
    e.begin = w->sensor_begin;
    e.begin_count = w->sensor_begin_count;
    e.end = w->sensor_end;
    e.end_count = w->sensor_end_count - w->sensor_end_pending;
    return e;
}

GA2D_API int ga2d_shape_get_sensor_overlaps(const ga2d_world *w, ga2d_shape_id sensor, ga2d_shape_id *out, int capacity)
{
    const ga2d__shape *se = ga2d__shape_lookup(w, sensor);
    int i;
    if (!se || !se->is_sensor) return 0;
    for (i = 0; out && i < se->visitor_count && i < capacity; ++i) out[i] = ga2d__shape_id_of(w, se->visitors[i]);
    return se->visitor_count;
}

/* ----------------------------------------- shapes: mass, slots and proxies */
/* A shape's exact mass properties at density rho in its body's frame (a
   segment has none). */
static ga2d_mass ga2d__shape_mass(const ga2d__shape *s, ga2d_real rho)
{
    ga2d_mass m;
    memset(&m, 0, sizeof m);
    switch (s->geom.type) {
    case GA2D_SHAPE_POLYGON: ga2d_polygon_mass_checked(&s->geom.as.polygon, rho, &m); break;
    case GA2D_SHAPE_CIRCLE: ga2d_circle_mass_checked(&s->geom.as.circle, rho, &m); break;
    case GA2D_SHAPE_CAPSULE: ga2d_capsule_mass_checked(&s->geom.as.capsule, rho, &m); break;
    default: m.center = ga2d_vec_scale(ga2d_vec_add(ga2d__segment_of(&s->geom)->point1, ga2d__segment_of(&s->geom)->point2), GA2D__R(0.5)); break;
    }
    return m;
}

/* How far a shape reaches from the point c of its body's frame. */
static ga2d_real ga2d__shape_reach(const ga2d__shape *s, ga2d_vec c)
{
    const ga2d_geometry *g = &s->geom;
    ga2d_real d = 0, e;
    int j;
    switch (g->type) {
    case GA2D_SHAPE_POLYGON:
        for (j = 0; j < g->as.polygon.count; ++j) {
            e = ga2d_vec_length(ga2d_vec_sub(g->as.polygon.vertices[j], c));
            d = e > d ? e : d;
        }
        return d + g->as.polygon.radius;
    case GA2D_SHAPE_CIRCLE: return ga2d_vec_length(ga2d_vec_sub(g->as.circle.center, c)) + g->as.circle.radius;
    case GA2D_SHAPE_CAPSULE:
        d = ga2d_vec_length(ga2d_vec_sub(g->as.capsule.center1, c));
        e = ga2d_vec_length(ga2d_vec_sub(g->as.capsule.center2, c));
        return (d > e ? d : e) + g->as.capsule.radius;
    default:
        d = ga2d_vec_length(ga2d_vec_sub(ga2d__segment_of(g)->point1, c));
        e = ga2d_vec_length(ga2d_vec_sub(ga2d__segment_of(g)->point2, c));
        return d > e ? d : e;
    }
}

/* How far a shape reaches inward from its surface to its middle: a round
   shape's radius, a polygon's least distance from its vertices' mean to
   an edge plus its radius (the thickness continuous collision measures a
   step's motion against); 0 for a segment. */
static ga2d_real ga2d__shape_inner_reach(const ga2d__shape *s)
{
    const ga2d_geometry *g = &s->geom;
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE: return g->as.circle.radius;
    case GA2D_SHAPE_CAPSULE: return g->as.capsule.radius;
    case GA2D_SHAPE_POLYGON: {
        const ga2d_polygon *p = &g->as.polygon;
        ga2d_vec m = ga2d_vec_make(0, 0);
        ga2d_real least = GA2D__MAX;
        int j;
        for (j = 0; j < p->count; ++j) m = ga2d_vec_add(m, p->vertices[j]);
        m = ga2d_vec_scale(m, 1 / (ga2d_real)p->count);
        for (j = 0; j < p->count; ++j) {
            ga2d_real d = ga2d_dot(p->normals[j], ga2d_vec_sub(p->vertices[j], m));
            least = d < least ? d : least;
        }
        return (least > 0 ? least : 0) + p->radius;
    }
    default: return 0;
    }
}

/* The shapes a body's mass sums: its list less shape `skip` and the
   segments of chain `skip_chain` (-1: none), then `extra` (NULL: none), a
   shape about to join the list's tail. */
typedef struct ga2d__shape_walk {
    const ga2d_world *w;
    int k, skip, skip_chain;
    const ga2d__shape *extra;
} ga2d__shape_walk;

static const ga2d__shape *ga2d__walk_next(ga2d__shape_walk *it)
{
    const ga2d__shape *e = it->extra;
    while (it->k >= 0) {
        const ga2d__shape *sh = &it->w->shapes[it->k];
        int k = it->k;
        it->k = sh->next;
        if (k != it->skip && (it->skip_chain < 0 || sh->chain != it->skip_chain)) return sh;
    }
    it->extra = NULL;
    return e;
}

/* A body's mass properties as its shapes sum them, and its centre's new
   place and velocity. */
typedef struct ga2d__mass_sum {
    ga2d_real mass, inertia;   /* as the body keeps them */
    ga2d_vec local_center, center, v;
} ga2d__mass_sum;

/* The body's mass, centre and inertia as the sum over its shapes (those
   ga2d__walk_next gives), about the first shape's centre c0 so that one
   shape's data are taken as they are: M = sum m_i, C = c0 + sum m_i (c_i
   - c0) / M, and by parallel axes I = sum I_i + m_i |c_i - C|^2.  Static
   and kinematic bodies take the centroid of their shapes' areas (density
   1) and no mass.  A dynamic body whose shapes have no mass gets mass 1
   and no inertia (it does not turn) until a shape or
   ga2d_body_set_mass_data gives it some.  The origin stays where it is
   (the centre moves with the rigid motion, so its velocity becomes v +
   (C' - C) Omega).  GA2D_ERR_MASS_OVERFLOW when a sum, the centre, its
   place or velocity, or an inverse would not be finite: shapes each
   accepted (each finite, within the coordinate bound) can sum past the
   range of ga2d_real, and the step could not recover from it. */
static ga2d_result ga2d__mass_sum_of(const ga2d_world *w, int slot, ga2d_vec origin, int skip, int skip_chain,
                                     const ga2d__shape *extra, ga2d__mass_sum *out)
{
    const ga2d__body *b = &w->bodies[slot];
    int dynamic = b->type == GA2D_BODY_DYNAMIC, count = 0;
    ga2d_real M = 0, I = 0;
    ga2d_vec c0 = ga2d_vec_make(0, 0), C, moment = ga2d_vec_make(0, 0);
    const ga2d__shape *sh;
    ga2d__shape_walk it;
    it.w = w;
    it.k = b->shape_head;
    it.skip = skip;
    it.skip_chain = skip_chain;
    it.extra = extra;
    while ((sh = ga2d__walk_next(&it)) != NULL) {
        ga2d_mass m = ga2d__shape_mass(sh, sh->is_sensor ? 0 : dynamic ? sh->density : 1);
        if (count++ == 0) c0 = m.center;
        else moment = ga2d_vec_add(moment, ga2d_vec_scale(ga2d_vec_sub(m.center, c0), m.mass));
        M += m.mass;
    }
    if (M > 0 && count > 1 && !ga2d__finite_vec(moment) && ga2d__finite(M)) {
        /* the moment about c0 passed the range (a heavy shape far from a
           light first one) while the centre need not: sum m_i / M (c_i -
           c0) instead, each term within the shapes' span (the plain sum
           keeps its bits wherever it is finite) */
        moment = ga2d_vec_make(0, 0);
        it.k = b->shape_head;
        it.extra = extra;
        while ((sh = ga2d__walk_next(&it)) != NULL) {
            ga2d_mass m = ga2d__shape_mass(sh, sh->is_sensor ? 0 : dynamic ? sh->density : 1);
            moment = ga2d_vec_add(moment, ga2d_vec_scale(ga2d_vec_sub(m.center, c0), m.mass / M));
        }
        C = ga2d_vec_add(c0, moment);
    } else {
        C = M > 0 && count > 1 ? ga2d_vec_add(c0, ga2d_vec_scale(moment, 1 / M)) : c0;
    }
    it.k = b->shape_head;
    it.extra = extra;
    while (dynamic && (sh = ga2d__walk_next(&it)) != NULL) {
        ga2d_mass m = ga2d__shape_mass(sh, sh->is_sensor ? 0 : sh->density);
        I += count > 1 ? m.inertia + m.mass * ga2d_vec_length_sq(ga2d_vec_sub(m.center, C)) : m.inertia;
    }
    out->local_center = C;
    out->center = ga2d_vec_add(origin, ga2d_rotate(b->sim.q, C));
    out->v = ga2d_vec_add(b->sim.v, ga2d_vec_scale(ga2d_vec_perp(ga2d_vec_sub(out->center, b->sim.center)), b->sim.w));
    out->mass = dynamic ? (M > 0 ? M : 1) : 0;
    out->inertia = dynamic && M > 0 ? I : 0;
    if (!ga2d__finite(M) || !ga2d__finite(I) || !ga2d__finite_vec(C) || !ga2d__finite_vec(out->center) || !ga2d__finite_vec(out->v) ||
        (dynamic && (!ga2d__finite(1 / out->mass) || (out->inertia > 0 && !ga2d__finite(1 / out->inertia)))))
        return GA2D_ERR_MASS_OVERFLOW;
    return GA2D_OK;
}

/* How far the body's shapes reach from its centre of mass (the fat boxes'
   swing, continuous collision's motion test), and its thinnest shape's
   inner reach: anew whenever its shapes or its centre change. */
static void ga2d__refresh_extent(const ga2d_world *w, ga2d__body *b)
{
    int k;
    b->extent = 0;
    b->min_extent = GA2D__MAX;
    for (k = b->shape_head; k >= 0; k = w->shapes[k].next) {
        ga2d_real d = ga2d__shape_reach(&w->shapes[k], b->sim.local_center), m = ga2d__shape_inner_reach(&w->shapes[k]);
        b->extent = d > b->extent ? d : b->extent;
        if (!w->shapes[k].is_sensor && m < b->min_extent) b->min_extent = m;
    }
    if (b->min_extent == GA2D__MAX) b->min_extent = b->extent;
}

/* The body takes its shapes' mass properties (ga2d__mass_sum_of, checked
   by the caller), and its extent is refreshed.  Its origin is kept, but
   the centre is what the body stores, and the origin read back from it
   (c - l q) rounds at the centre's size: a centre far out (a shape
   10^7 m away) moves the origin, and the shapes with it, by up to a
   metre.  So the callers refit the body's proxies after (a static body
   is never refit by a step). */
static void ga2d__update_mass(ga2d_world *w, int slot, ga2d_vec origin)
{
    ga2d__body *b = &w->bodies[slot];
    ga2d__mass_sum s;
    ga2d__mass_sum_of(w, slot, origin, -1, -1, NULL, &s);
    b->sim.local_center = s.local_center;
    b->sim.v = s.v;
    b->sim.center = s.center;
    b->sim.center0 = s.center;
    b->sim.q0 = b->sim.q;
    b->sim.dq = ga2d_rotor_identity();
    b->mass = s.mass;
    b->inertia = s.inertia;
    b->sim.inv_mass = b->sim.inv_inertia = 0;
    if (b->type == GA2D_BODY_DYNAMIC) {
        b->sim.inv_mass = 1 / b->mass;
        b->sim.inv_inertia = b->fixed_rotation || !(b->inertia > 0) ? 0 : 1 / b->inertia;
        if (b->fixed_rotation) b->sim.w = 0;
    }
    ga2d__refresh_extent(w, b);
    b->sim.field_valid = 0;
}

/* Room for one more shape, its queue entry and its proxy in the tree of
   a body that moves or not: 0 when memory runs out (nothing changed). */
static int ga2d__shape_reserve(ga2d_world *w, int moves)
{
    int slot = w->shape_free >= 0 ? w->shape_free : w->shape_used;
    if (!ga2d__grow(&w->mem, (void **)&w->shapes, &w->shape_capacity, slot + 1, sizeof *w->shapes)) return 0;
    if (!ga2d__grow(&w->mem, (void **)&w->move_buf, &w->move_capacity, w->shape_used + 1, sizeof *w->move_buf)) return 0;
    return ga2d__tree_reserve(&w->mem, &w->trees[moves], 1);
}

/* A checked shape onto a body, in reserved room: appended to the body's
   list; its proxy waits for ga2d__shape_proxies (the box needs the body's
   mass). */
static int ga2d__shape_add(ga2d_world *w, int slot, const ga2d_shape_def *def, const ga2d_geometry *g)
{
    ga2d__body *b = &w->bodies[slot];
    ga2d__shape *sh;
    int k = w->shape_free >= 0 ? w->shape_free : w->shape_used;
    if (k == w->shape_used) {
        w->shapes[k].generation = 0;
        ++w->shape_used;
    } else {
        w->shape_free = w->shapes[k].next_free;
    }
    sh = &w->shapes[k];
    {
        uint32_t generation = sh->generation + 1;
        memset(sh, 0, sizeof *sh);
        sh->generation = generation ? generation : 1; /* 0 is the null id's */
    }
    sh->type = (int)g->type;
    sh->geom = *g;
    sh->body = slot;
    sh->tree = b->type != GA2D_BODY_STATIC;
    sh->radius = ga2d__shape_radius(sh);
    sh->next = -1;
    sh->next_free = -1;
    sh->proxy = -1;
    sh->density = def->density;
    sh->friction = def->friction;
    sh->restitution = def->restitution;
    sh->filter = def->filter;
    sh->user_data = def->user_data;
    sh->is_sensor = def->is_sensor != 0;
    sh->sensor_events = def->enable_sensor_events != 0;
    sh->pre_solve_events = def->enable_pre_solve_events != 0;
    sh->hit_events = def->enable_hit_events != 0;
    w->hit_shapes += sh->hit_events;
    sh->tangent_speed = def->tangent_speed;
    sh->rolling_resistance = def->rolling_resistance;
    sh->chain = -1;
    w->sensor_count += sh->is_sensor;
    if (b->shape_tail >= 0) w->shapes[b->shape_tail].next = k;
    else b->shape_head = k;
    b->shape_tail = k;
    ++b->shape_count;
    ++w->shape_count;
    return k;
}

/* A new shape's proxy: its fat box in its body's tree, queued for pairs. */
static void ga2d__shape_proxy(ga2d_world *w, int k)
{
    ga2d__shape *sh = &w->shapes[k];
    const ga2d__body *b = &w->bodies[sh->body];
    sh->proxy = ga2d__tree_create(ga2d__tree_of(w, sh), ga2d__fatten(ga2d__shape_aabb(sh, ga2d__body_xf(b)), ga2d__margin(w, b)), k,
                                  sh->filter.category_bits);
    w->bodies[sh->body].boxes_changed = w->box_clock;
    ga2d__buffer_move(w, k);
}

/* A shape's proxy and queue entry go, and its slot is freed (its
   contacts are gone already).  The queue entry goes with it: the slot,
   reused before the next step, queues again, and the buffer is sized for
   one entry per slot (destroy-create cycles between steps overflowed it). */
static void ga2d__shape_free(ga2d_world *w, int k)
{
    ga2d__shape *sh = &w->shapes[k];
    ga2d__body *b = &w->bodies[sh->body];
    int prev = -1, j;
    ga2d__sensor_forget(w, k);
    ga2d__tree_destroy(ga2d__tree_of(w, sh), sh->proxy);
    if (sh->in_move)
        for (j = 0; j < w->move_count; ++j)
            if (w->move_buf[j] == k) {
                w->move_buf[j] = w->move_buf[--w->move_count];
                break;
            }
    for (j = b->shape_head; j != k; j = w->shapes[j].next) prev = j;
    if (prev >= 0) w->shapes[prev].next = sh->next;
    else b->shape_head = sh->next;
    if (b->shape_tail == k) b->shape_tail = prev;
    --b->shape_count;
    --w->shape_count;
    w->hit_shapes -= sh->hit_events;
    sh->in_move = 0;
    sh->type = -1;
    sh->generation = ga2d__next_generation(sh->generation);
    sh->next_free = w->shape_free;
    w->shape_free = k;
}

/* ---------------------------------------------------------------- bodies */
GA2D_API ga2d_body_def ga2d_default_body_def(void)
{
    ga2d_body_def d;
    memset(&d, 0, sizeof d);
    d.type = GA2D_BODY_STATIC;
    d.rotor = ga2d_rotor_identity();
    d.density = GA2D__R(GA2D_DEFAULT_DENSITY);
    d.friction = GA2D__R(GA2D_DEFAULT_FRICTION);
    d.gravity_scale = 1;
    d.is_awake = 1;
    d.filter = ga2d_default_filter();
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

/* The one place a body def's zeros become defaults (see "Defs"); a zero
   rotor means the identity in every def. */
static void ga2d__resolve_body_def(const ga2d_body_def *in, ga2d_body_def *out)
{
    ga2d_body_def dflt = ga2d_default_body_def();
    int stamped = in->internal_cookie == GA2D_DEF_COOKIE;
    memset(out, 0, sizeof *out);
    out->internal_cookie = GA2D_DEF_COOKIE;
    GA2D__TAKE(type);
    GA2D__TAKE(position);
    out->rotor = in->rotor.c == 0 && in->rotor.s == 0 ? dflt.rotor : in->rotor;
    GA2D__TAKE(velocity);
    GA2D__TAKE(angular_velocity);
    GA2D__TAKE(polygon);
    GA2D__TAKE(density);
    GA2D__TAKE(friction);
    GA2D__TAKE(restitution);
    GA2D__TAKE(linear_damping);
    GA2D__TAKE(angular_damping);
    GA2D__TAKE(gravity_scale);
    GA2D__TAKE(fixed_rotation);
    GA2D__TAKE(is_awake);
    GA2D__TAKE(user_data);
    GA2D__TAKE(filter);
    GA2D__TAKE(is_bullet);
}


GA2D_API ga2d_result ga2d_body_def_validate(const ga2d_body_def *def)
{
    ga2d_body_def d;
    if (!def) return GA2D_ERR_INVALID_ARGUMENT;
    ga2d__resolve_body_def(def, &d);
    return ga2d__body_def_check(&d);
}

/* Adds slot i to the moving list (capacity ensured by the caller). */
static void ga2d__moving_add(ga2d_world *w, int i)
{
    w->bodies[i].box_slack = -1;
    w->bodies[i].move_index = w->moving_count;
    w->moving[w->moving_count++] = i;
    w->moving_dynamic += w->bodies[i].type == GA2D_BODY_DYNAMIC;
}

static void ga2d__moving_remove(ga2d_world *w, int i)
{
    int k = w->bodies[i].move_index, last;
    if (k < 0) return;
    last = w->moving[--w->moving_count];
    w->moving[k] = last;
    w->bodies[last].move_index = k;
    w->bodies[i].move_index = -1;
    w->moving_dynamic -= w->bodies[i].type == GA2D_BODY_DYNAMIC;
}

static ga2d_body_id ga2d__body_create(ga2d_world *w, const ga2d_body_def *def)
{
    ga2d_body_id id = ga2d_body_id_null();
    ga2d__body *b;
    ga2d_geometry g;
    int slot, moves, shape = -1;
    moves = def->type != GA2D_BODY_STATIC;
    /* every allocation first: a failure leaves the world as it was */
    slot = w->free_head >= 0 ? w->free_head : w->body_used;
    if (!ga2d__grow(&w->mem, (void **)&w->bodies, &w->body_capacity, slot + 1, sizeof *w->bodies)) return id;
    if (!ga2d__grow(&w->mem, (void **)&w->wake_queue, &w->wake_capacity, w->body_used + 1, sizeof *w->wake_queue) ||
        !ga2d__reserve_slots(w, w->body_used + 1))
        return id;
    if (moves) {
        /* room for every slot: sleeping bodies come back without allocating */
        if (!ga2d__grow(&w->mem, (void **)&w->moving, &w->moving_capacity, w->body_used + 1, sizeof *w->moving))
            return id;
        if (w->def.integrator == GA2D_INTEGRATOR_RK4 &&
            !ga2d__reserve_rk4(w, w->moving_capacity))
            return id;
        if (!ga2d__reserve_moving(w, w->moving_capacity)) return id;
    }
    if (def->polygon.count > 0) {
        if (!ga2d__shape_reserve(w, moves)) return id;
        memset(&g, 0, sizeof g);
        g.type = GA2D_SHAPE_POLYGON;
        ga2d__polygon_remake(&def->polygon, &g.as.polygon); /* validated above */
    }

    if (slot == w->body_used) {
        w->bodies[slot].generation = 0;
        ++w->body_used;
    } else {
        w->free_head = w->bodies[slot].next_free;
    }
    b = &w->bodies[slot];
    {
        uint32_t generation = b->generation + 1;
        memset(b, 0, sizeof *b);
        b->generation = generation ? generation : 1; /* 0 is the null id's */
    }
    b->type = (int)def->type;
    b->shape_head = b->shape_tail = -1;
    b->sim.q = (def->rotor.c == 0 && def->rotor.s == 0) ? ga2d_rotor_identity() : ga2d_rotor_normalize(def->rotor);
    b->sim.center = def->position;
    b->sim.linear_damping = def->linear_damping;
    b->sim.angular_damping = def->angular_damping;
    b->sim.gravity_scale = def->gravity_scale;
    b->fixed_rotation = def->fixed_rotation != 0;
    b->is_bullet = def->is_bullet != 0;
    b->awake = def->is_awake != 0;
    b->user_data = def->user_data;
    b->move_index = -1;
    b->next_free = -1;
    b->contact_head = b->contact_tail = -1;
    b->joint_head = -1;
    if (def->polygon.count > 0) {
        ga2d_shape_def sd = ga2d_default_shape_def();
        sd.density = def->density;
        sd.friction = def->friction;
        sd.restitution = def->restitution;
        sd.filter = def->filter;
        shape = ga2d__shape_add(w, slot, &sd, &g);
    }
    /* bodies that never step keep their start pose */
    ga2d__update_mass(w, slot, def->position);
    if (def->type != GA2D_BODY_DYNAMIC) b->awake = 1; /* only dynamic bodies sleep */
    if (moves) {
        b->sim.v = def->velocity;
        b->sim.w = (b->fixed_rotation && def->type == GA2D_BODY_DYNAMIC) ? 0 : def->angular_velocity;
        if (b->awake) ga2d__moving_add(w, slot);
    }
    if (shape >= 0) ga2d__shape_proxy(w, shape);
    ++w->body_count;
    return ga2d__id_of(w, slot);
}

GA2D_API ga2d_body_id ga2d_body_create(ga2d_world *w, const ga2d_body_def *def)
{
    ga2d_body_id id = ga2d_body_id_null();
    ga2d_body_def d;
    if (!w || w->lock || !def) return id;
    ga2d__resolve_body_def(def, &d);
    if (ga2d__body_def_check(&d) != GA2D_OK) return id;
    ga2d__enter(w);
    id = ga2d__body_create(w, &d);
    ga2d__leave(w);
    return id;
}

static void ga2d__chain_free(ga2d_world *w, int k);

GA2D_API ga2d_result ga2d_body_destroy(ga2d_world *w, ga2d_body_id id)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    int slot;
    if (r != GA2D_OK) return r;
    slot = ga2d__slot(id);
    ga2d__enter(w); /* waking, sensors and chains allocate and free through the hooks */
    {
        /* what rested on it must not hang in the air: wake its neighbours */
        int link;
        for (link = ga2d__first_edge(w, slot); link >= 0; link = ga2d__next_edge(w, link)) {
            const ga2d__contact *ct = &w->contacts[link >> 1];
            if (ct->touching) ga2d__wake(w, ga2d__edge_other(w, link));
        }
    }
    while (b->joint_head >= 0) ga2d__joint_free(w, b->joint_head >> 1); /* wakes what hung from it */
    ga2d__destroy_body_contacts(w, slot, 0);
    while (b->shape_head >= 0) ga2d__shape_free(w, b->shape_head);
    {
        int k;
        for (k = 0; k < w->chain_used; ++k)
            if (w->chains[k].type == 0 && w->chains[k].body == slot) ga2d__chain_free(w, k);
    }
    ga2d__moving_remove(w, slot);
    b->type = -1;
    b->generation = ga2d__next_generation(b->generation);
    b->next_free = w->free_head;
    w->free_head = slot;
    --w->body_count;
    ga2d__leave(w);
    return GA2D_OK;
}

GA2D_API int ga2d_body_is_valid(const ga2d_world *w, ga2d_body_id id) { return ga2d__lookup(w, id) != NULL; }

GA2D_API int ga2d_body_is_awake(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? b->awake : 0;
}

/* Sleeping on request puts the body's whole touching island to sleep;
   waking wakes it.  Only dynamic bodies sleep. */
GA2D_API ga2d_result ga2d_body_set_awake(ga2d_world *w, ga2d_body_id id, int awake)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    int n, i;
    if (r != GA2D_OK) return r;
    if (awake) {
        ga2d__wake(w, ga2d__slot(id));
        return GA2D_OK;
    }
    if (b->type != GA2D_BODY_DYNAMIC || !b->awake) return GA2D_OK;
    n = ga2d__flip_island(w, ga2d__slot(id), 1);
    for (i = 0; i < n; ++i) {
        w->bodies[w->wake_queue[i]].sleep_time = 0;
        ga2d__put_to_sleep(w, w->wake_queue[i]);
    }
    return GA2D_OK;
}

/* ------------------------------------------------------------------ shapes */
GA2D_API ga2d_shape_id ga2d_shape_id_null(void) { ga2d_shape_id id; id.index1 = 0; id.generation = 0; return id; }
GA2D_API int ga2d_shape_id_is_null(ga2d_shape_id id) { return id.index1 == 0; }
GA2D_API int ga2d_shape_id_equal(ga2d_shape_id a, ga2d_shape_id b) { return a.index1 == b.index1 && a.generation == b.generation; }


/* Refuses a change while the world is stepping or in a callback. */
static ga2d_result ga2d__shape_writable(const ga2d_world *w, ga2d_shape_id id, ga2d__shape **out)
{
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    *out = ga2d__shape_lookup(w, id);
    return *out ? GA2D_OK : GA2D_ERR_STALE_ID;
}

GA2D_API ga2d_shape_def ga2d_default_shape_def(void)
{
    ga2d_shape_def d;
    memset(&d, 0, sizeof d);
    d.density = GA2D__R(GA2D_DEFAULT_DENSITY);
    d.friction = GA2D__R(GA2D_DEFAULT_FRICTION);
    d.filter = ga2d_default_filter();
    d.enable_sensor_events = 1;
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

/* The one place a shape def's zeros become defaults (see "Defs"). */
static void ga2d__resolve_shape_def(const ga2d_shape_def *in, ga2d_shape_def *out)
{
    ga2d_shape_def dflt = ga2d_default_shape_def();
    int stamped = in->internal_cookie == GA2D_DEF_COOKIE;
    memset(out, 0, sizeof *out);
    out->internal_cookie = GA2D_DEF_COOKIE;
    GA2D__TAKE(density);
    GA2D__TAKE(friction);
    GA2D__TAKE(restitution);
    GA2D__TAKE(filter);
    GA2D__TAKE(user_data);
    GA2D__TAKE(is_sensor);
    GA2D__TAKE(enable_sensor_events);
    GA2D__TAKE(enable_pre_solve_events);
    GA2D__TAKE(enable_hit_events);
    GA2D__TAKE(tangent_speed);
    GA2D__TAKE(rolling_resistance);
}

GA2D_API ga2d_result ga2d_shape_create_checked(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def,
                                              const ga2d_geometry *g, ga2d_shape_id *out)
{
    ga2d_shape_def d;
    ga2d_geometry clean;
    ga2d__body *b;
    ga2d_result r;
    int k;
    if (out) *out = ga2d_shape_id_null();
    if (!w || !def || !g || !out) return GA2D_ERR_INVALID_ARGUMENT;
    if ((r = ga2d__writable(w, body, &b)) != GA2D_OK) return r;
    if (g->type == GA2D_SHAPE_CHAIN_SEGMENT) return GA2D_ERR_INVALID_ARGUMENT; /* only on a chain */
    ga2d__resolve_shape_def(def, &d);
    if (!ga2d__finite(d.density) || !ga2d__finite(d.friction) || !ga2d__finite(d.restitution) || !ga2d__finite(d.tangent_speed) ||
        !ga2d__finite(d.rolling_resistance))
        return GA2D_ERR_NOT_FINITE;
    if (d.density < 0 || d.friction < 0 || d.restitution < 0 || d.rolling_resistance < 0) return GA2D_ERR_INVALID_ARGUMENT;
    if ((r = ga2d__geometry_check(g, b->type, d.density, &clean)) != GA2D_OK) return r;
    {
        /* the body's sums with the shape added must stay finite */
        ga2d__shape extra;
        ga2d__mass_sum s;
        memset(&extra, 0, sizeof extra);
        extra.geom = clean;
        extra.density = d.density;
        extra.is_sensor = d.is_sensor != 0;
        extra.chain = -1;
        if ((r = ga2d__mass_sum_of(w, ga2d__slot(body), ga2d__body_origin(b), -1, -1, &extra, &s)) != GA2D_OK) return r;
    }
    ga2d__enter(w);
    if (!ga2d__shape_reserve(w, b->type != GA2D_BODY_STATIC)) {
        ga2d__leave(w);
        return GA2D_ERR_OUT_OF_MEMORY;
    }
    b = &w->bodies[ga2d__slot(body)];
    k = ga2d__shape_add(w, ga2d__slot(body), &d, &clean);
    ga2d__update_mass(w, ga2d__slot(body), ga2d__body_origin(b));
    ga2d__shape_proxy(w, k);
    ga2d__update_proxy(w, ga2d__slot(body)); /* see ga2d__update_mass */
    ga2d__wake(w, ga2d__slot(body));
    *out = ga2d__shape_id_of(w, k);
    ga2d__leave(w);
    return GA2D_OK;
}

/* The typed makers: a geometry each, copied into the union's start. */
static ga2d_shape_id ga2d__shape_create(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, ga2d_shape_type type,
                                        const void *src, size_t size)
{
    ga2d_geometry g;
    ga2d_shape_id id = ga2d_shape_id_null();
    if (!src) return id;
    memset(&g, 0, sizeof g);
    g.type = type;
    memcpy(&g.as, src, size);
    ga2d_shape_create_checked(w, body, def, &g, &id);
    return id;
}

GA2D_API ga2d_shape_id ga2d_shape_create_circle(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_circle *c)
{
    return ga2d__shape_create(w, body, def, GA2D_SHAPE_CIRCLE, c, sizeof *c);
}

GA2D_API ga2d_shape_id ga2d_shape_create_capsule(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_capsule *c)
{
    return ga2d__shape_create(w, body, def, GA2D_SHAPE_CAPSULE, c, sizeof *c);
}

GA2D_API ga2d_shape_id ga2d_shape_create_polygon(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_polygon *p)
{
    return ga2d__shape_create(w, body, def, GA2D_SHAPE_POLYGON, p, sizeof *p);
}

GA2D_API ga2d_shape_id ga2d_shape_create_segment(ga2d_world *w, ga2d_body_id body, const ga2d_shape_def *def, const ga2d_segment *sg)
{
    return ga2d__shape_create(w, body, def, GA2D_SHAPE_SEGMENT, sg, sizeof *sg);
}

static void ga2d__shape_remove(ga2d_world *w, int k);

GA2D_API ga2d_result ga2d_shape_destroy(ga2d_world *w, ga2d_shape_id id, int update_body_mass)
{
    ga2d__shape *sh;
    ga2d_result r = ga2d__shape_writable(w, id, &sh);
    int slot;
    if (r != GA2D_OK) return r;
    if (sh->type == GA2D_SHAPE_CHAIN_SEGMENT) return GA2D_ERR_INVALID_ARGUMENT; /* ga2d_chain_destroy */
    slot = sh->body;
    if (update_body_mass) {
        /* the sums without it must stay finite too (they are taken about
           another first shape, and the centre moves) */
        ga2d__mass_sum s;
        r = ga2d__mass_sum_of(w, slot, ga2d__body_origin(&w->bodies[slot]), (int)id.index1 - 1, -1, NULL, &s);
        if (r != GA2D_OK) return r;
    }
    ga2d__enter(w); /* sensors, the tree and waking allocate and free through the hooks */
    ga2d__shape_remove(w, (int)id.index1 - 1);
    if (update_body_mass) {
        ga2d__update_mass(w, slot, ga2d__body_origin(&w->bodies[slot]));
        ga2d__update_proxy(w, slot);
    }
    ga2d__wake(w, slot);
    ga2d__leave(w);
    return GA2D_OK;
}

/* A shape goes: its contacts end, what rested on it wakes, its slot is
   freed. */
static void ga2d__shape_remove(ga2d_world *w, int k)
{
    int slot = w->shapes[k].body, link = ga2d__first_edge(w, slot);
    while (link >= 0) {
        int ci = link >> 1, next = ga2d__next_edge(w, link);
        const ga2d__contact *ct = &w->contacts[ci];
        if (ct->shape_a == k || ct->shape_b == k) {
            if (ct->touching) ga2d__wake(w, ga2d__edge_other(w, link));
            ga2d__destroy_contact(w, ci);
        }
        link = next;
    }
    ga2d__shape_free(w, k);
}

GA2D_API int ga2d_shape_is_valid(const ga2d_world *w, ga2d_shape_id id) { return ga2d__shape_lookup(w, id) != NULL; }

GA2D_API ga2d_body_id ga2d_shape_body(const ga2d_world *w, ga2d_shape_id id)
{
    const ga2d__shape *sh = ga2d__shape_lookup(w, id);
    return sh ? ga2d__id_of(w, sh->body) : ga2d_body_id_null();
}

GA2D_API ga2d_shape_type ga2d_shape_get_type(const ga2d_world *w, ga2d_shape_id id)
{
    const ga2d__shape *sh = ga2d__shape_lookup(w, id);
    return sh ? (ga2d_shape_type)sh->type : GA2D_SHAPE_TYPE_COUNT;
}

GA2D_API ga2d_geometry ga2d_shape_geometry(const ga2d_world *w, ga2d_shape_id id)
{
    const ga2d__shape *sh = ga2d__shape_lookup(w, id);
    ga2d_geometry g;
    memset(&g, 0, sizeof g);
    g.type = GA2D_SHAPE_TYPE_COUNT;
    return sh ? sh->geom : g;
}

GA2D_API void *ga2d_shape_user_data(const ga2d_world *w, ga2d_shape_id id)
{
    const ga2d__shape *sh = ga2d__shape_lookup(w, id);
    return sh ? sh->user_data : NULL;
}

/* A material change reaches the shape's contacts at once. */
static void ga2d__shape_materials(ga2d_world *w, int k)
{
    int link;
    for (link = ga2d__first_edge(w, w->shapes[k].body); link >= 0; link = ga2d__next_edge(w, link)) {
        ga2d__contact *ct = &w->contacts[link >> 1];
        const ga2d__shape *pa = &w->shapes[ct->shape_a], *pb = &w->shapes[ct->shape_b];
        if (ct->shape_a != k && ct->shape_b != k) continue;
        ct->friction = ga2d__mix_friction(pa->friction, pb->friction);
        ct->restitution = pa->restitution > pb->restitution ? pa->restitution : pb->restitution;
    }
}

GA2D_API ga2d_result ga2d_shape_set_friction(ga2d_world *w, ga2d_shape_id id, ga2d_real friction)
{
    ga2d__shape *sh;
    ga2d_result r = ga2d__shape_writable(w, id, &sh);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(friction)) return GA2D_ERR_NOT_FINITE;
    if (friction < 0) return GA2D_ERR_INVALID_ARGUMENT;
    ga2d__wake(w, sh->body); /* a body at rest on a slope may slide now */
    sh->friction = friction;
    ga2d__shape_materials(w, (int)id.index1 - 1);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_shape_set_restitution(ga2d_world *w, ga2d_shape_id id, ga2d_real restitution)
{
    ga2d__shape *sh;
    ga2d_result r = ga2d__shape_writable(w, id, &sh);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(restitution)) return GA2D_ERR_NOT_FINITE;
    if (restitution < 0) return GA2D_ERR_INVALID_ARGUMENT;
    sh->restitution = restitution;
    ga2d__shape_materials(w, (int)id.index1 - 1);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_shape_set_filter(ga2d_world *w, ga2d_shape_id id, ga2d_filter f)
{
    ga2d__shape *sh;
    ga2d_result r = ga2d__shape_writable(w, id, &sh);
    int k = (int)id.index1 - 1, link;
    if (r != GA2D_OK) return r;
    ga2d__wake(w, sh->body);
    sh->filter = f;
    ga2d__tree_set_category(ga2d__tree_of(w, sh), sh->proxy, f.category_bits);
    link = ga2d__first_edge(w, sh->body);
    while (link >= 0) {
        int ci = link >> 1, next = ga2d__next_edge(w, link);
        const ga2d__contact *ct = &w->contacts[ci];
        if ((ct->shape_a == k || ct->shape_b == k) && !ga2d__pair_wanted(w, ct->shape_a, ct->shape_b)) ga2d__destroy_contact(w, ci);
        link = next;
    }
    ga2d__buffer_move(w, k); /* pairs it may now make */
    return GA2D_OK;
}

GA2D_API ga2d_filter ga2d_shape_filter(const ga2d_world *w, ga2d_shape_id id)
{
    const ga2d__shape *sh = ga2d__shape_lookup(w, id);
    ga2d_filter f;
    memset(&f, 0, sizeof f);
    return sh ? sh->filter : f;
}

GA2D_API ga2d_aabb ga2d_shape_fat_aabb(const ga2d_world *w, ga2d_shape_id id)
{
    const ga2d__shape *sh = ga2d__shape_lookup(w, id);
    ga2d_aabb box;
    memset(&box, 0, sizeof box);
    return sh ? ga2d__fat_box(w, sh) : box;
}

GA2D_API ga2d_aabb ga2d_shape_aabb(const ga2d_world *w, ga2d_shape_id id)
{
    const ga2d__shape *sh = ga2d__shape_lookup(w, id);
    ga2d_aabb box;
    memset(&box, 0, sizeof box);
    return sh ? ga2d__shape_aabb(sh, ga2d__body_xf(&w->bodies[sh->body])) : box;
}

GA2D_API int ga2d_body_get_shapes(const ga2d_world *w, ga2d_body_id id, ga2d_shape_id *out, int capacity)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    int k, n = 0;
    if (!b) return 0;
    for (k = b->shape_head; k >= 0; k = w->shapes[k].next, ++n)
        if (out && n < capacity) out[n] = ga2d__shape_id_of(w, k);
    return n;
}

/* ---------------------------------------------------------------- chains */
GA2D_API ga2d_chain_def ga2d_default_chain_def(void)
{
    ga2d_chain_def d;
    memset(&d, 0, sizeof d);
    d.friction = GA2D__R(GA2D_DEFAULT_FRICTION);
    d.filter = ga2d_default_filter();
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

/* The one place a chain def's zeros become defaults (see "Defs"). */
static void ga2d__resolve_chain_def(const ga2d_chain_def *in, ga2d_chain_def *out)
{
    ga2d_chain_def dflt = ga2d_default_chain_def();
    int stamped = in->internal_cookie == GA2D_DEF_COOKIE;
    memset(out, 0, sizeof *out);
    out->internal_cookie = GA2D_DEF_COOKIE;
    GA2D__TAKE(points);
    GA2D__TAKE(count);
    GA2D__TAKE(is_loop);
    GA2D__TAKE(friction);
    GA2D__TAKE(restitution);
    GA2D__TAKE(filter);
    GA2D__TAKE(user_data);
}

/* A resolved chain def's points and materials against their bounds. */
static ga2d_result ga2d__chain_def_check(const ga2d_chain_def *d)
{
    int i, n;
    ga2d_result r;
    if (!d->points || d->count < 0 || d->count > GA2D__MAX_BODIES) return GA2D_ERR_INVALID_ARGUMENT;
    if (d->count < (d->is_loop ? 3 : 2)) return GA2D_ERR_TOO_FEW_POINTS;
    if (!ga2d__finite(d->friction) || !ga2d__finite(d->restitution)) return GA2D_ERR_NOT_FINITE;
    if (d->friction < 0 || d->restitution < 0) return GA2D_ERR_INVALID_ARGUMENT;
    for (i = 0; i < d->count; ++i)
        if ((r = ga2d__point_check(d->points[i])) != GA2D_OK) return r;
    n = d->is_loop ? d->count : d->count - 1;
    for (i = 0; i < n; ++i)
        if (!ga2d__ends_apart(d->points[i], d->points[(i + 1) % d->count])) return GA2D_ERR_REPEATED_POINTS;
    return GA2D_OK;
}

static ga2d_chain_id ga2d__chain_id_of(const ga2d_world *w, int k)
{
    ga2d_chain_id id;
    id.index1 = (uint32_t)k + 1;
    id.generation = w->chains[k].generation ^ w->tag;
    return id;
}

/* The live chain an id names, or NULL. */
static ga2d__chain *ga2d__chain_lookup(const ga2d_world *w, ga2d_chain_id id)
{
    return GA2D__LIVE(w, ga2d__chain, chains, chain_used, id);
}

/* A chain slot's segments are gone: the slot is freed. */
static void ga2d__chain_free(ga2d_world *w, int k)
{
    ga2d__chain *c = &w->chains[k];
    GA2D__FREE_ARRAY(&w->mem, c->shapes, c->count);
    c->shapes = NULL;
    c->count = 0;
    c->type = -1;
    c->generation = ga2d__next_generation(c->generation);
    c->next_free = w->chain_free;
    w->chain_free = k;
    --w->chain_count;
}

/* Segment i of a chain of n points: its ends and ghosts.  An open chain's
   end turns down a right angle (its ghost lies behind it), so the end is
   rounded over as a lone segment's is.  The made-up ghost is twice the
   end segment e's length away: apart from the end whenever the two points
   are (ga2d__ends_apart: 2|e| > 64 eps (S0 + Sg) follows from |e| > 64
   eps (S0 + S1), the sizes S being L1 norms, as S0 <= S1 + sqrt2 |e| and
   Sg <= S0 + 2 sqrt2 |e|), and within GA2D__GHOST_BOUND, so the world's
   snapshot loads what it made. */
static ga2d_chain_segment ga2d__chain_segment_at(const ga2d_chain_def *d, int i)
{
    ga2d_chain_segment cs;
    int n = d->count;
    const ga2d_vec *p = d->points;
    cs.segment.point1 = p[i];
    cs.segment.point2 = p[(i + 1) % n];
    if (d->is_loop) {
        cs.ghost1 = p[(i + n - 1) % n];
        cs.ghost2 = p[(i + 2) % n];
    } else {
        ga2d_vec e0 = ga2d_vec_sub(p[1], p[0]), e1 = ga2d_vec_sub(p[n - 1], p[n - 2]);
        cs.ghost1 = i > 0 ? p[i - 1] : ga2d_vec_sub(p[0], ga2d_vec_scale(ga2d__left(e0), 2));
        cs.ghost2 = i + 2 < n ? p[i + 2] : ga2d_vec_sub(p[n - 1], ga2d_vec_scale(ga2d__left(e1), 2));
    }
    return cs;
}

GA2D_API ga2d_result ga2d_chain_create_checked(ga2d_world *w, ga2d_body_id body, const ga2d_chain_def *def, ga2d_chain_id *out)
{
    ga2d_chain_def d;
    ga2d_shape_def sd;
    ga2d__body *b;
    ga2d__chain *c;
    ga2d_result r;
    int n, i, k, *shapes, moves;
    if (out) memset(out, 0, sizeof *out);
    if (!w || !def || !out) return GA2D_ERR_INVALID_ARGUMENT;
    if ((r = ga2d__writable(w, body, &b)) != GA2D_OK) return r;
    if (b->type == GA2D_BODY_DYNAMIC) return GA2D_ERR_INVALID_ARGUMENT;
    ga2d__resolve_chain_def(def, &d);
    if ((r = ga2d__chain_def_check(&d)) != GA2D_OK) return r;
    n = d.is_loop ? d.count : d.count - 1;
    /* each segment as the snapshot loader will check it: what a world
       makes, its snapshot loads */
    for (i = 0; i < n; ++i) {
        ga2d_geometry g;
        memset(&g, 0, sizeof g);
        g.type = GA2D_SHAPE_CHAIN_SEGMENT;
        g.as.chain_segment = ga2d__chain_segment_at(&d, i);
        if ((r = ga2d__geometry_check(&g, b->type, 0, &g)) != GA2D_OK) return r;
        if (i == 0) {
            /* segments have no area: the body's sums with the chain are
               those with its first segment alone (its centre when the
               body has no area yet) */
            ga2d__shape extra;
            ga2d__mass_sum s;
            memset(&extra, 0, sizeof extra);
            extra.geom = g;
            extra.chain = -1;
            if ((r = ga2d__mass_sum_of(w, ga2d__slot(body), ga2d__body_origin(b), -1, -1, &extra, &s)) != GA2D_OK) return r;
        }
    }
    moves = b->type != GA2D_BODY_STATIC;
    /* every allocation first: the shapes as if none were free, their
       queue entries, proxies, the chain slot and its list */
    ga2d__enter(w);
    k = w->chain_free >= 0 ? w->chain_free : w->chain_used;
    shapes = NULL;
    if (!ga2d__grow(&w->mem, (void **)&w->shapes, &w->shape_capacity, w->shape_used + n, sizeof *w->shapes) ||
        !ga2d__grow(&w->mem, (void **)&w->move_buf, &w->move_capacity, w->shape_used + n, sizeof *w->move_buf) ||
        !ga2d__tree_reserve(&w->mem, &w->trees[moves], n) ||
        !ga2d__grow(&w->mem, (void **)&w->chains, &w->chain_capacity, k + 1, sizeof *w->chains) ||
        !(shapes = (int *)ga2d__alloc(&w->mem, (size_t)n * sizeof *shapes))) {
        ga2d__leave(w);
        return GA2D_ERR_OUT_OF_MEMORY;
    }
    if (k == w->chain_used) {
        w->chains[k].generation = 0;
        ++w->chain_used;
    } else {
        w->chain_free = w->chains[k].next_free;
    }
    c = &w->chains[k];
    {
        uint32_t generation = c->generation + 1;
        memset(c, 0, sizeof *c);
        c->generation = generation ? generation : 1;
    }
    c->body = ga2d__slot(body);
    c->shapes = shapes;
    c->count = n;
    c->next_free = -1;
    ++w->chain_count;
    sd = ga2d_default_shape_def();
    sd.density = 0;
    sd.friction = d.friction;
    sd.restitution = d.restitution;
    sd.filter = d.filter;
    sd.user_data = d.user_data;
    for (i = 0; i < n; ++i) {
        ga2d_geometry g;
        memset(&g, 0, sizeof g);
        g.type = GA2D_SHAPE_CHAIN_SEGMENT;
        g.as.chain_segment = ga2d__chain_segment_at(&d, i);
        shapes[i] = ga2d__shape_add(w, c->body, &sd, &g);
        w->shapes[shapes[i]].chain = k;
    }
    ga2d__update_mass(w, c->body, ga2d__body_origin(&w->bodies[c->body]));
    for (i = 0; i < n; ++i) ga2d__shape_proxy(w, shapes[i]);
    ga2d__update_proxy(w, c->body);
    *out = ga2d__chain_id_of(w, k);
    ga2d__leave(w);
    return GA2D_OK;
}

GA2D_API ga2d_chain_id ga2d_chain_create(ga2d_world *w, ga2d_body_id body, const ga2d_chain_def *def)
{
    ga2d_chain_id id;
    ga2d_chain_create_checked(w, body, def, &id);
    return id;
}

GA2D_API ga2d_result ga2d_chain_destroy(ga2d_world *w, ga2d_chain_id id)
{
    ga2d__chain *c;
    int i, slot;
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    if (!(c = ga2d__chain_lookup(w, id))) return GA2D_ERR_STALE_ID;
    slot = c->body;
    {
        ga2d__mass_sum s;
        ga2d_result r = ga2d__mass_sum_of(w, slot, ga2d__body_origin(&w->bodies[slot]), -1, (int)id.index1 - 1, NULL, &s);
        if (r != GA2D_OK) return r;
    }
    ga2d__enter(w);
    for (i = 0; i < c->count; ++i) ga2d__shape_remove(w, c->shapes[i]);
    ga2d__chain_free(w, (int)id.index1 - 1);
    ga2d__update_mass(w, slot, ga2d__body_origin(&w->bodies[slot]));
    ga2d__update_proxy(w, slot);
    ga2d__leave(w);
    return GA2D_OK;
}

GA2D_API int ga2d_chain_get_segments(const ga2d_world *w, ga2d_chain_id id, ga2d_shape_id *out, int capacity)
{
    const ga2d__chain *c = ga2d__chain_lookup(w, id);
    int i;
    if (!c) return 0;
    for (i = 0; out && i < c->count && i < capacity; ++i) out[i] = ga2d__shape_id_of(w, c->shapes[i]);
    return c->count;
}

/* ------------------------------------------------------------ body getters */
GA2D_API ga2d_body_type ga2d_body_get_type(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? (ga2d_body_type)b->type : GA2D_BODY_STATIC;
}

GA2D_API ga2d_vec ga2d_body_position(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? ga2d__body_origin(b) : ga2d_vec_make(0, 0);
}

GA2D_API ga2d_rotor ga2d_body_rotor(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? b->sim.q : ga2d_rotor_identity();
}

GA2D_API ga2d_real ga2d_body_angle(const ga2d_world *w, ga2d_body_id id) { return ga2d_rotor_angle(ga2d_body_rotor(w, id)); }

GA2D_API ga2d_transform ga2d_body_transform(const ga2d_world *w, ga2d_body_id id)
{
    return ga2d_transform_make(ga2d_body_position(w, id), ga2d_body_rotor(w, id));
}

GA2D_API ga2d_vec ga2d_body_center(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? b->sim.center : ga2d_vec_make(0, 0);
}

GA2D_API ga2d_vec ga2d_body_velocity(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? b->sim.v : ga2d_vec_make(0, 0);
}

GA2D_API ga2d_real ga2d_body_angular_velocity(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? b->sim.w : 0;
}

/* v + r Omega with r = p - c: r (w e12) = w perp(r) */
GA2D_API ga2d_vec ga2d_body_velocity_at(const ga2d_world *w, ga2d_body_id id, ga2d_vec p)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    if (!b) return ga2d_vec_make(0, 0);
    return ga2d_vec_add(b->sim.v, ga2d_vec_scale(ga2d_vec_perp(ga2d_vec_sub(p, b->sim.center)), b->sim.w));
}

GA2D_API ga2d_mass ga2d_body_mass_data(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    ga2d_mass m;
    memset(&m, 0, sizeof m);
    if (!b) return m;
    m.mass = b->mass;
    m.center = b->sim.local_center;
    m.inertia = b->inertia;
    return m;
}

GA2D_API ga2d_real ga2d_body_kinetic_energy(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    if (!b || b->type != GA2D_BODY_DYNAMIC) return 0;
    return (b->mass * ga2d_dot(b->sim.v, b->sim.v) + (b->sim.inv_inertia > 0 ? b->inertia * b->sim.w * b->sim.w : 0)) / 2;
}

GA2D_API const ga2d_polygon *ga2d_body_polygon(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    int k;
    if (!b) return NULL;
    for (k = b->shape_head; k >= 0; k = w->shapes[k].next)
        if (w->shapes[k].type == GA2D_SHAPE_POLYGON) return &w->shapes[k].geom.as.polygon;
    return NULL;
}

GA2D_API void *ga2d_body_user_data(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? b->user_data : NULL;
}

/* ------------------------------------------------------------ body setters */
GA2D_API ga2d_result ga2d_body_set_transform(ga2d_world *w, ga2d_body_id id, ga2d_vec position, ga2d_rotor q)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite_vec(position) || !ga2d__finite(q.c) || !ga2d__finite(q.s)) return GA2D_ERR_NOT_FINITE;
    if (!ga2d__coordinate_ok(position)) return GA2D_ERR_TOO_LARGE;
    {
        ga2d_vec u, c;
        /* zero, or too small to normalize (subnormal): no direction */
        if (ga2d_vec_normalize(ga2d_vec_make(q.c, q.s), &u) == 0) return GA2D_ERR_INVALID_ARGUMENT;
        /* the centre must be finite too (a huge position plus a huge
           centre of mass from ga2d_body_set_mass_data can overflow) */
        c = ga2d_vec_add(position, ga2d_rotate(ga2d__rotor(u.x, u.y), b->sim.local_center));
        if (!ga2d__finite_vec(c)) return GA2D_ERR_NOT_FINITE;
        b->sim.q = ga2d__rotor(u.x, u.y);
        b->sim.center = c;
    }
    ga2d__wake(w, ga2d__slot(id));
    b->sim.center0 = b->sim.center;
    b->sim.q0 = b->sim.q;
    b->sim.dq = ga2d_rotor_identity();
    b->sim.field_valid = 0;
    ga2d__update_proxy(w, ga2d__slot(id));
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_set_velocity(ga2d_world *w, ga2d_body_id id, ga2d_vec v)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite_vec(v)) return GA2D_ERR_NOT_FINITE;
    if (b->type == GA2D_BODY_STATIC) return GA2D_ERR_INVALID_ARGUMENT; /* a static body cannot move */
    ga2d__wake(w, ga2d__slot(id));
    b->sim.v = v;
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_set_angular_velocity(ga2d_world *w, ga2d_body_id id, ga2d_real omega)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(omega)) return GA2D_ERR_NOT_FINITE;
    if (b->type == GA2D_BODY_STATIC) return GA2D_ERR_INVALID_ARGUMENT;
    /* fixed rotation, or inertia 0 from set_mass_data: it cannot turn */
    if (b->type == GA2D_BODY_DYNAMIC && b->sim.inv_inertia == 0 && omega != 0) return GA2D_ERR_INVALID_ARGUMENT;
    ga2d__wake(w, ga2d__slot(id));
    b->sim.w = omega;
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_set_mass_data(ga2d_world *w, ga2d_body_id id, ga2d_mass m)
{
    ga2d__body *b;
    ga2d_vec center, v;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(m.mass) || !ga2d__finite(m.inertia) || !ga2d__finite_vec(m.center)) return GA2D_ERR_NOT_FINITE;
    if (b->type != GA2D_BODY_DYNAMIC || !(m.mass > 0) || m.inertia < 0) return GA2D_ERR_INVALID_ARGUMENT;
    if (!ga2d__coordinate_ok(m.center)) return GA2D_ERR_TOO_LARGE;
    if (!ga2d__finite(1 / m.mass) || (m.inertia > 0 && !ga2d__finite(1 / m.inertia))) return GA2D_ERR_INVALID_ARGUMENT;
    center = ga2d_vec_add(ga2d__body_origin(b), ga2d_rotate(b->sim.q, m.center));
    /* the new centre moves with the rigid motion: v + (c' - c) Omega */
    v = ga2d_vec_add(b->sim.v, ga2d_vec_scale(ga2d_vec_perp(ga2d_vec_sub(center, b->sim.center)), b->sim.w));
    /* a centre so far out that the world position overflows: refused,
       like any input that would make the state not finite */
    if (!ga2d__finite_vec(center) || !ga2d__finite_vec(v)) return GA2D_ERR_NOT_FINITE;
    ga2d__wake(w, ga2d__slot(id));
    b->sim.center = center;
    b->sim.v = v;
    b->sim.local_center = m.center;
    b->mass = m.mass;
    b->sim.inv_mass = 1 / m.mass;
    b->inertia = m.inertia;
    b->sim.inv_inertia = (b->fixed_rotation || m.inertia == 0) ? 0 : 1 / m.inertia;
    if (b->sim.inv_inertia == 0) b->sim.w = 0;
    b->sim.field_valid = 0;
    ga2d__refresh_extent(w, b); /* measured from the new centre */
    ga2d__update_proxy(w, ga2d__slot(id)); /* see ga2d__update_mass */
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_set_gravity_scale(ga2d_world *w, ga2d_body_id id, ga2d_real scale)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(scale)) return GA2D_ERR_NOT_FINITE;
    ga2d__wake(w, ga2d__slot(id));
    b->sim.gravity_scale = scale;
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_set_damping(ga2d_world *w, ga2d_body_id id, ga2d_real linear, ga2d_real angular)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(linear) || !ga2d__finite(angular)) return GA2D_ERR_NOT_FINITE;
    if (linear < 0 || angular < 0) return GA2D_ERR_INVALID_ARGUMENT;
    b->sim.linear_damping = linear;
    b->sim.angular_damping = angular;
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_set_user_data(ga2d_world *w, ga2d_body_id id, void *user_data)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    b->user_data = user_data;
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_set_bullet(ga2d_world *w, ga2d_body_id id, int bullet)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    b->is_bullet = bullet != 0;
    return GA2D_OK;
}

GA2D_API int ga2d_body_is_bullet(const ga2d_world *w, ga2d_body_id id)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    return b ? b->is_bullet : 0;
}

/* -------------------------------------------------- forces and impulses */
/* Forces are allowed inside the force callback (they go to the field's
   accumulator there); everything else needs an unlocked world. */
static ga2d_result ga2d__force_target(ga2d_world *w, ga2d_body_id id, ga2d__body **out)
{
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock && w->lock != (GA2D__LOCK_STEP | GA2D__LOCK_FIELD)) return GA2D_ERR_LOCKED;
    *out = ga2d__lookup(w, id);
    return *out ? GA2D_OK : GA2D_ERR_STALE_ID;
}

/* A push from the force field on a sleeping body (the step is under way
   and the body is in none of its arrays): a push that is not zero wakes
   the body's island at the step's end (ga2d__grant_wakes), and the
   island joins the next step, where the field pushes it again.  Nothing
   is added to the sleeping body's state. */
static ga2d_result ga2d__field_wakes(ga2d_world *w, ga2d__body *b, int pushes)
{
    if (pushes && !b->wake_request) {
        b->wake_request = 1;
        ++w->wake_requests;
    }
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_apply_force(ga2d_world *w, ga2d_body_id id, ga2d_vec force, ga2d_vec point)
{
    ga2d__body *b;
    ga2d_result r = ga2d__force_target(w, id, &b);
    ga2d_real tau;
    if (r != GA2D_OK) return r;
    if (!ga2d__finite_vec(force) || !ga2d__finite_vec(point)) return GA2D_ERR_NOT_FINITE;
    if (b->type != GA2D_BODY_DYNAMIC) return GA2D_OK;
    tau = ga2d_wedge(ga2d_vec_sub(point, b->sim.center), force); /* r ^ F */
    if (!b->awake && (w->lock & GA2D__LOCK_FIELD)) return ga2d__field_wakes(w, b, force.x != 0 || force.y != 0 || tau != 0);
    {
        ga2d_vec *f = (w->lock & GA2D__LOCK_FIELD) ? &b->sim.field_force : &b->sim.force;
        ga2d_real *t = (w->lock & GA2D__LOCK_FIELD) ? &b->sim.field_torque : &b->sim.torque;
        ga2d_vec nf = ga2d_vec_add(*f, force);
        ga2d_real nt = *t + tau;
        /* finite inputs can still overflow the sums: refuse, keep the old */
        if (!ga2d__finite_vec(nf) || !ga2d__finite(nt)) return GA2D_ERR_NOT_FINITE;
        if (!(w->lock & GA2D__LOCK_FIELD)) ga2d__wake(w, ga2d__slot(id));
        *f = nf;
        *t = nt;
    }
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_apply_force_to_center(ga2d_world *w, ga2d_body_id id, ga2d_vec force)
{
    ga2d__body *b;
    ga2d_result r = ga2d__force_target(w, id, &b);
    if (r != GA2D_OK) return r;
    return ga2d_body_apply_force(w, id, force, b->sim.center);
}

GA2D_API ga2d_result ga2d_body_apply_torque(ga2d_world *w, ga2d_body_id id, ga2d_real torque)
{
    ga2d__body *b;
    ga2d_result r = ga2d__force_target(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(torque)) return GA2D_ERR_NOT_FINITE;
    if (b->type != GA2D_BODY_DYNAMIC) return GA2D_OK;
    if (!b->awake && (w->lock & GA2D__LOCK_FIELD)) return ga2d__field_wakes(w, b, torque != 0);
    {
        ga2d_real *t = (w->lock & GA2D__LOCK_FIELD) ? &b->sim.field_torque : &b->sim.torque;
        if (!ga2d__finite(*t + torque)) return GA2D_ERR_NOT_FINITE;
        if (!(w->lock & GA2D__LOCK_FIELD)) ga2d__wake(w, ga2d__slot(id));
        *t += torque;
    }
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_apply_impulse(ga2d_world *w, ga2d_body_id id, ga2d_vec impulse, ga2d_vec point)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite_vec(impulse) || !ga2d__finite_vec(point)) return GA2D_ERR_NOT_FINITE;
    if (b->type != GA2D_BODY_DYNAMIC) return GA2D_OK;
    {
        ga2d_vec v = ga2d_vec_add(b->sim.v, ga2d_vec_scale(impulse, b->sim.inv_mass));
        ga2d_real om = b->sim.w + b->sim.inv_inertia * ga2d_wedge(ga2d_vec_sub(point, b->sim.center), impulse); /* I^-1 (r ^ P) */
        if (!ga2d__finite_vec(v) || !ga2d__finite(om)) return GA2D_ERR_NOT_FINITE;
        ga2d__wake(w, ga2d__slot(id));
        b->sim.v = v;
        b->sim.w = om;
    }
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_body_apply_angular_impulse(ga2d_world *w, ga2d_body_id id, ga2d_real impulse)
{
    ga2d__body *b;
    ga2d_result r = ga2d__writable(w, id, &b);
    if (r != GA2D_OK) return r;
    if (!ga2d__finite(impulse)) return GA2D_ERR_NOT_FINITE;
    if (b->type != GA2D_BODY_DYNAMIC) return GA2D_OK;
    if (!ga2d__finite(b->sim.w + b->sim.inv_inertia * impulse)) return GA2D_ERR_NOT_FINITE;
    ga2d__wake(w, ga2d__slot(id));
    b->sim.w += b->sim.inv_inertia * impulse;
    return GA2D_OK;
}

/* ======================================================== collision stages */
/* The stages flag what book-keeping must visit in bit sets (a bit per
   item, set by the item's own stage), visited in item order. */
/* The first set bit from i on, below n, or -1. */
static int ga2d__next_bit(const uint64_t *bits, int i, int n)
{
    for (; i < n; i = (i | 63) + 1) {
        uint64_t w = bits[i >> 6] >> (i & 63);
        if (w) {
            while (!(w & 1)) {
                w >>= 1;
                ++i;
            }
            return i < n ? i : -1;
        }
    }
    return -1;
}

/* Bits [0, n) cleared. */
static void ga2d__bits_zero(uint64_t *bits, int n)
{
    if (n > 0) memset(bits, 0, (size_t)((n + 63) / 64) * sizeof *bits);
}

/* How far any point of a body's shapes has moved along either axis since
   the step began (or, before the step's start, since the last one's):
   its centre's displacement along the axis that moved most, plus the
   chord its turn sweeps at its extent, r |1 - dq| <= r (|1 - c| + |s|)
   for dq = q q0~. */
static GA2D__HOT ga2d_real ga2d__moved_since_start(const ga2d__body *b)
{
    ga2d_vec d = ga2d_vec_sub(b->sim.center, b->sim.center0);
    ga2d_rotor dq = ga2d_rotor_mul(b->sim.q, ga2d_rotor_inverse(b->sim.q0));
    ga2d_real chord = (GA2D__FABS(1 - dq.c) + GA2D__FABS(dq.s)) * b->extent, shift = GA2D__FABS(d.x);
    shift = GA2D__FABS(d.y) > shift ? GA2D__FABS(d.y) : shift;
    return shift + chord;
}

/* The rounding a body's box tests allow for: GA2D__BOX_GUARD ulps of its
   coordinates' size (a shape's box at a pose is a few roundings of
   |c| + extent off the exact one; the reach's sums and the slack's
   differences a few more). */
#define GA2D__BOX_GUARD 32
static ga2d_real ga2d__box_guard(const ga2d__body *b, ga2d_real reach)
{
    return GA2D__R(GA2D__BOX_GUARD) * GA2D__EPS * (GA2D__FABS(b->sim.center.x) + GA2D__FABS(b->sim.center.y) + b->extent + reach);
}

/* Whether a body's tree boxes, as its shapes' boxes last found them at a
   step's start, still pass both of ga2d__needs_refit's tests in this step,
   told from its motion since alone, no shape's box found: each shape has
   moved by at most m along an axis (ga2d__moved_since_start), and its
   reach adds at most |v|max dt plus its swing, so the boxes still hold
   it while the slack found then (its boxes' nearest side past its
   shape's) is at least m, the reach and the guard; and each box, which
   reached at most `excess` past its shape, reaches at most excess + m
   past it now, within the 4 margins beyond the margin that a box
   re-fitted now would have (ga2d__needs_refit's second test).  A body at
   rest finds its shapes' boxes again once its motion has used its
   slack.  The test only ever says yes where the shapes' boxes would: a
   body it turns away takes that test, so the boxes are the same bits. */
static GA2D__HOT int ga2d__boxes_kept(const ga2d_world *w, ga2d__body *b, ga2d_real dt)
{
    ga2d_real moved, turn, speed, reach, guard;
    if (!(b->box_slack >= 0)) return 0;
    moved = ga2d__moved_since_start(b);
    turn = GA2D__FABS(b->sim.w) * dt;
    speed = GA2D__FABS(b->sim.v.x) > GA2D__FABS(b->sim.v.y) ? GA2D__FABS(b->sim.v.x) : GA2D__FABS(b->sim.v.y);
    reach = speed * dt + b->extent * (turn < 1 ? turn : 1);
    guard = ga2d__box_guard(b, reach);
    /* written to fail on a NaN */
    if (!(moved + reach + guard <= b->box_slack && b->box_excess + moved + 2 * guard <= 5 * ga2d__margin(w, b))) return 0;
    b->box_slack -= moved + guard;
    b->box_excess += moved + guard;
    return 1;
}

/* Stage, over the moving bodies: a body any of whose shapes' fat boxes no
   longer holds what it can reach in this step gets new boxes for all its
   shapes, written into their own tree leaves (a leaf's box is read by
   nothing else until ga2d__refit_proxies moves it in the tree), and its
   bit.  Most bodies are told theirs still fit from their motion alone
   (ga2d__boxes_kept); the others' slack and excess are found from their
   shapes' boxes.  The slack is kept for ga2d__mark_strays too. */
static void ga2d__mark_refits(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__counts n = {0, 0, 0, 0, 0};
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        int s, refit = 0;
        ga2d_aabb fat, now;
        ga2d_real slack = GA2D__R(GA2D_MAX_COORDINATE), excess = 0;
        if (ga2d__boxes_kept(w, b, c->dt)) {
            ++n.boxes_kept;
            continue;
        }
        for (s = b->shape_head; s >= 0 && !refit; s = w->shapes[s].next) {
            refit = ga2d__needs_refit(w, b, &w->shapes[s], &fat, &now);
            ga2d__box_gaps(ga2d__fat_box(w, &w->shapes[s]), now, &slack, &excess);
        }
        if (refit) {
            slack = GA2D__R(GA2D_MAX_COORDINATE);
            excess = 0;
            if (b->shape_count == 1) {
                const ga2d__shape *sh = &w->shapes[b->shape_head];
                ga2d__tree_of(w, sh)->nodes[sh->proxy].box = fat;
                ga2d__box_gaps(fat, now, &slack, &excess);
            } else {
                for (s = b->shape_head; s >= 0; s = w->shapes[s].next) {
                    const ga2d__shape *sh = &w->shapes[s];
                    ga2d__needs_refit(w, b, sh, &fat, &now);
                    ga2d__tree_of(w, sh)->nodes[sh->proxy].box = fat;
                    ga2d__box_gaps(fat, now, &slack, &excess);
                }
            }
            c->refits[k >> 6] |= (uint64_t)1 << (k & 63);
            b->boxes_changed = w->box_clock;
        }
        b->box_slack = slack;
        b->box_excess = excess;
    }
    ga2d__counts_put(c, begin, &n);
}

/* Stage, over the moving bodies, after the substeps (and continuous
   collision): a body a joint or contact carried out of any of its tree
   leaves (the boxes hold what its velocity at the step's start could
   reach) gets its boxes grown now to hold the boxes the next step's
   ga2d__mark_refits would give it, so that world queries between steps
   see every shape where it is.  (Grown, never shrunk: the pairs its old
   boxes made stay until the next step's narrowphase, as they would
   have.)  A body whose motion in the step is within the slack its boxes
   had at the start stays inside them: its shapes moved by at most its
   centre's motion (per axis) and the chord its turn sweeps at its
   extent, r |1 - dq| <= r (|1 - c| + |s|) for dq = q q0~; the guard
   covers the rounding of the boxes' coordinates.  Only the others pay
   for tight boxes. */
static void ga2d__mark_strays(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int k;
    for (k = begin; k < end; ++k) {
        const ga2d__body *b = &w->bodies[w->moving[k]];
        ga2d_real guard = 16 * GA2D__EPS * (GA2D__FABS(b->sim.center.x) + GA2D__FABS(b->sim.center.y) + b->extent);
        ga2d_transform x;
        int s, out = 0;
        if (ga2d__moved_since_start(b) + guard <= b->box_slack) continue;
        x = ga2d__body_xf(b);
        for (s = b->shape_head; s >= 0 && !out; s = w->shapes[s].next) {
            const ga2d__shape *sh = &w->shapes[s];
            out = !ga2d_aabb_contains(ga2d__tree_of(w, sh)->nodes[sh->proxy].box, ga2d__shape_aabb(sh, x));
        }
        if (!out) continue;
        for (s = b->shape_head; s >= 0; s = w->shapes[s].next) {
            const ga2d__shape *sh = &w->shapes[s];
            ga2d_aabb fat, now, *box = &ga2d__tree_of(w, sh)->nodes[sh->proxy].box;
            ga2d__needs_refit(w, b, sh, &fat, &now);
            *box = ga2d_aabb_union(*box, fat);
        }
        /* its boxes grew: their excess is past what box_slack's body
           knew, but the motion that took the shape out of them is more
           than its slack, so the next step finds them anew */
        c->refits[k >> 6] |= (uint64_t)1 << (k & 63);
    }
}

/* Stage, over the leaves of c->stray_tree given new boxes this step,
   with every box above them tightened: each that has left its sibling at
   some level (ga2d__tree_strayed) is flagged for moving, its entry in
   the tree's units made ~leaf.  The tree is only read, so the leaves are
   looked at in ranges on the workers, all in the tree as tightened. */
static void ga2d__flag_strays(ga2d__step_context *c, int begin, int end)
{
    ga2d__tree *t = c->stray_tree;
    int i;
    for (i = begin; i < end; ++i)
        if (ga2d__tree_strayed(t, t->units[i])) t->units[i] = ~t->units[i];
}

/* Book-keeping: the marked bodies' new shape boxes are fitted into their
   trees: every box above them tightened, then each that left its
   parent's box in the tree so tightened moved (taken out, put back by the
   heuristic), in the moving list's order (the trees' shape depends on it;
   the pairs they give, on the boxes alone); the shapes queue for pair
   finding.  Then the queue is sorted, without destroyed shapes and
   repeats (a slot destroyed and reused). */
#define GA2D__TIGHTEN_ALL 16 /* past 1 leaf moved in this many: the whole tree refitted */
static void ga2d__refit_proxies(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int k, n;
    for (k = ga2d__next_bit(c->refits, 0, w->moving_count); k >= 0; k = ga2d__next_bit(c->refits, k + 1, w->moving_count)) {
        int s;
        for (s = w->bodies[w->moving[k]].shape_head; s >= 0; s = w->shapes[s].next) {
            ga2d__shape *sh = &w->shapes[s];
            ga2d__tree *t = ga2d__tree_of(w, sh);
            t->units[t->moved++] = sh->proxy;
            ga2d__buffer_move(w, s);
        }
    }
    for (k = 0; k < 2; ++k) {
        ga2d__tree *t = &w->trees[k];
        int i;
        if (t->moved * 2 > t->leaves) { /* most left their boxes: built anew */
            ga2d__tree_rebuild(t);
            t->moved = 0;
            ++w->counters.trees_rebuilt;
            continue;
        }
        if (t->moved * GA2D__TIGHTEN_ALL > t->leaves) {
            ga2d__tree_tighten(t, 1);
        } else if (t->moved > 0) {
            for (i = 0; i < t->moved; ++i) ga2d__tree_mark(t, t->units[i]);
            ga2d__tree_tighten(t, 0);
        }
        c->stray_tree = t;
        ga2d__run_split(c, ga2d__flag_strays, t->moved);
        for (i = 0; i < t->moved; ++i)
            if (t->units[i] < 0) ga2d__tree_move(t, ~t->units[i], t->nodes[~t->units[i]].box);
        t->moved = 0;
    }
    /* the queue's order is not the results': of two queued shapes the
       smaller slot finds their pair (ga2d__pair_found), and the new pairs
       are made in key order (ga2d__create_pairs); a shape is queued once
       (ga2d__buffer_move).  (It was sorted, and that cost joint_grid 0.1
       ms a step.) */
    for (k = 0, n = 0; k < w->move_count; ++k) {
        int s = w->move_buf[k];
        if (w->shapes[s].type >= 0 && w->shapes[s].in_move) w->move_buf[n++] = s;
    }
    w->move_count = n;
    w->new_pair_count = 0;
}

/* Stage, over the queued shapes: each queued shape (moved out of its
   box, created, teleported, refiltered) is queried against the moving
   tree (and, if its body moves, the static tree); the pairs it finds are
   listed. */
static void ga2d__find_pairs(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int k;
    for (k = begin; k < end; ++k) {
        int s = w->move_buf[k];
        ga2d__pair_query q;
        const ga2d_filter *f = &w->shapes[s].filter;
        ga2d_aabb box = ga2d__fat_box(w, &w->shapes[s]);
        /* the shapes its mask lets in (ga2d_should_collide); a positive
           group lets its own in whatever their categories */
        uint32_t mask = f->group_index > 0 ? GA2D__ALL_CATEGORIES : f->mask_bits;
        q.w = w;
        q.self = s;
        q.count = 0;
        ga2d__tree_query(&w->trees[1], box, mask, ga2d__pair_found, &q);
        if (w->bodies[w->shapes[s].body].type != GA2D_BODY_STATIC) ga2d__tree_query(&w->trees[0], box, mask, ga2d__pair_found, &q);
        ga2d__pairs_flush(&q);
    }
}

/* Book-keeping: the new pairs' contacts are created in key order, so the
   result is a function of the world's state alone, and the queue empties. */
static void ga2d__create_pairs(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int k, n;
    if (w->new_pair_count > 1) qsort(w->new_pairs, (size_t)w->new_pair_count, sizeof *w->new_pairs, ga2d__cmp_u64);
    for (k = 0, n = w->new_pair_count; k < n; ++k) {
        uint64_t key = w->new_pairs[k];
        if (k > 0 && w->new_pairs[k - 1] == key) continue;
        if (!ga2d__create_contact(w, (int)(key >> 32), (int)(uint32_t)key)) c->error = GA2D_ERR_OUT_OF_MEMORY;
    }
    /* out of memory: some pairs were not made, so every queued shape stays
       queued and is searched again next step (pairs already made are kept) */
    if (c->error == GA2D_ERR_OUT_OF_MEMORY) return;
    for (k = 0; k < w->move_count; ++k) w->shapes[w->move_buf[k]].in_move = 0;
    w->move_count = 0;
}

/* A point's impulses taken over from point j of the last manifold. */
static void ga2d__take_impulses(ga2d_manifold_point *p, const ga2d_manifold *last, int j)
{
    p->normal_impulse = last->points[j].normal_impulse;
    p->tangent_impulse = last->points[j].tangent_impulse;
    p->persisted = 1;
}

/* Warm starting: each point of a new manifold m takes the impulses of the
   last manifold's point with its id; a point whose id is new takes those
   of a last point that no id claimed and that lay within `near` of it (A's
   anchors compared: the relative ones, so nothing large is subtracted).
   One touch can be named two ways: when two faces are nearly parallel
   (as in a resting pile of rounded polygons), which of them is the
   reference turns on a tolerance the faces' tilt sits at, so rounding
   flips it between steps, and each flip renamed both points.  Started
   cold, a loaded contact dropped its load for a step; in float a pile's
   rounding flipped one such pair every few steps, and the kicks fed a
   cycle that never settled (1.6e-2 m/s after 300 s, bodies 100 x their
   rest speed).  `near` is half a slop: as far as ga2d__reuse_manifold
   lets a point be carried and still be the same touch. */
static void ga2d__warm_points(const ga2d_manifold *last, ga2d_manifold *m, ga2d_real near)
{
    int i, j, taken = 0; /* bit j: last point j gave its impulses */
    for (i = 0; i < m->count; ++i)
        for (j = 0; j < last->count; ++j)
            if (last->points[j].id == m->points[i].id) {
                ga2d__take_impulses(&m->points[i], last, j);
                taken |= 1 << j;
            }
    for (i = 0; i < m->count; ++i) {
        ga2d_real best = near;
        int k = -1;
        if (m->points[i].persisted) continue;
        for (j = 0; j < last->count; ++j) {
            ga2d_real d;
            if (taken & (1 << j)) continue;
            d = ga2d__length(ga2d_vec_sub(m->points[i].anchor_a, last->points[j].anchor_a));
            if (d <= best) {
                best = d;
                k = j;
            }
        }
        if (k < 0) continue;
        ga2d__take_impulses(&m->points[i], last, k);
        taken |= 1 << k;
    }
}

/* Whether two bodies' shapes are all farther apart than `gap`: their
   centres' distance less both extents (each bounds how far its shapes
   reach from the centre) is beyond it by more than the rounding of that
   sum, of the extents and of the narrowphase's own separations (a few
   eps of the coordinates and extents involved; 64 as the polygon checks
   allow).  Then the narrowphase, asked for points within `gap`, finds
   none: skipping it changes no bit. */
#define GA2D__BEYOND_ROUNDING 64
static int ga2d__beyond(const ga2d__body *a, const ga2d__body *b, ga2d_real gap)
{
    ga2d_vec d = ga2d_vec_sub(b->sim.center, a->sim.center);
    ga2d_real size = GA2D__FABS(a->sim.center.x) + GA2D__FABS(a->sim.center.y) + GA2D__FABS(b->sim.center.x) +
                     GA2D__FABS(b->sim.center.y) + a->extent + b->extent;
    ga2d_real apart = ga2d__length(d) - a->extent - b->extent;
    return apart > gap + GA2D__R(GA2D__BEYOND_ROUNDING) * GA2D__EPS * size;
}

/* Stage, over the contact pool: each contact whose fat boxes still
   overlap gets a new manifold (or its last one carried along,
   ga2d__reuse_manifold), whose points take over the impulses of the old
   points with the same id (warm starting).  What changes in the world
   (events, destruction, waking) is left to ga2d__contact_changes. */
/* How far apart a pair's points are kept: as far as it can close in one
   step, for speculative points only let bodies approach up to the gap
   (found only for a pair collided anew or apart: a carried one needs
   none). */
static ga2d_real ga2d__pair_margin(const ga2d__step_context *c, const ga2d__body *a, const ga2d__body *b)
{
    ga2d_real reach = ga2d__length(ga2d_vec_sub(b->sim.v, a->sim.v)) + GA2D__FABS(a->sim.w) * a->extent +
                      GA2D__FABS(b->sim.w) * b->extent;
    return c->world->speculative + reach * c->dt;
}

/* Whether neither body's fat boxes changed since the contact's were last
   seen to overlap: they overlap still, and the shapes and tree leaves (two
   random reads each, half of the stage's time in a 22 000-body pile) are
   not read.  The clock moves on after the stage, so a change after it
   (the user's moves, new shapes) comes after the check.  Stray boxes
   (ga2d__mark_strays) only grow, and boxes that overlap still do when
   they grow: they are not a change here. */
static GA2D__HOT int ga2d__boxes_unchanged(const ga2d__contact *ct, const ga2d__body *a, const ga2d__body *b)
{
    return ct->boxes_checked != 0 && a->boxes_changed <= ct->boxes_checked && b->boxes_changed <= ct->boxes_checked;
}

static void ga2d__collide_contacts(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int ci, carried = 0;
    for (ci = begin; ci < end; ++ci) {
        ga2d__contact *ct = &w->contacts[ci];
        const ga2d__body *a, *b;
        ga2d_transform xa, xb;
        ga2d_manifold m;
        ga2d_real margin;
        int touching;
        /* a contact further on, then its bodies once it is in (with only the
           record a stride away asked for, its read stalled: 18 % of
           large_pyramid's narrowphase) */
        if (ci + 2 * GA2D__PREFETCH_AHEAD < end) GA2D__PREFETCH_CONTACT(&ct[2 * GA2D__PREFETCH_AHEAD]);
        if (ci + GA2D__PREFETCH_AHEAD < end && ct[GA2D__PREFETCH_AHEAD].next_free == -2) { /* its bodies */
            GA2D__PREFETCH_READ(&w->bodies[ct[GA2D__PREFETCH_AHEAD].a]);
            GA2D__PREFETCH_READ(&w->bodies[ct[GA2D__PREFETCH_AHEAD].b]);
        }
        if (ct->next_free != -2) continue;
        a = &w->bodies[ct->a];
        b = &w->bodies[ct->b];
        /* a pair with nothing awake that moves has nothing new to say */
        if (!(a->awake && a->type != GA2D_BODY_STATIC) && !(b->awake && b->type != GA2D_BODY_STATIC)) continue;
        if (!ga2d__boxes_unchanged(ct, a, b)) {
            if (!ga2d_aabb_overlaps(ga2d__fat_box(w, &w->shapes[ct->shape_a]), ga2d__fat_box(w, &w->shapes[ct->shape_b]))) {
                ct->flags = GA2D__CONTACT_DISJOINT;
                c->changed[ci >> 6] |= (uint64_t)1 << (ci & 63);
                continue;
            }
            ct->boxes_checked = w->box_clock;
        }
        /* most pairs of a tumbling pile are boxes that meet, not bodies:
           one already apart that stays beyond the margin stays as it is */
        margin = ct->touching ? 0 : ga2d__pair_margin(c, a, b);
        if (!ct->touching && ga2d__beyond(a, b, margin)) continue;
        xa = ga2d__body_xf(a);
        xb = ga2d__body_xf(b);
        if (ga2d__reuse_manifold(w, ct, a, b, xa, xb)) {
            ++carried;
        } else {
            if (ct->touching) margin = ga2d__pair_margin(c, a, b);
            ga2d__collide_geometries(&w->shapes[ct->shape_a].geom, xa, &w->shapes[ct->shape_b].geom, xb, w->slop,
                                     margin, &m);
            ga2d__hold_manifold(&ct->held, xa, xb, &m);
            ga2d__warm_points(&ct->manifold, &m, GA2D__R(0.5) * w->slop);
            touching = m.count > 0;
            if (!touching && ct->touching) { /* the end is reported with the last touching manifold */
                ct->flags |= GA2D__CONTACT_ENDED;
                ct->end_normal = m.normal;
            } else {
                ct->manifold = m;
            }
            if (touching && !ct->touching) ct->flags |= GA2D__CONTACT_BEGAN;
            ct->touching = touching;
        }
        if (ct->touching && (!a->awake || !b->awake)) ct->flags |= GA2D__CONTACT_WAKES;
        if (ct->flags) c->changed[ci >> 6] |= (uint64_t)1 << (ci & 63);
    }
    c->tally[begin / GA2D__SPLIT_BLOCK] = carried; /* a range's own slot (ranges start on blocks) */
}

/* Book-keeping: the manifolds carried, summed over the ranges' slots. */
static void ga2d__count_carried(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int k, n = (w->contact_used + GA2D__SPLIT_BLOCK - 1) / GA2D__SPLIT_BLOCK;
    for (k = 0; k < n; ++k) w->counters.manifolds_carried += c->tally[k];
}

/* Book-keeping before the narrowphase: a clear bit for every pool contact.
   Out of memory, the step reports it and keeps the last manifolds. */
static int ga2d__reserve_changes(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int blocks = (w->contact_used + GA2D__SPLIT_BLOCK - 1) / GA2D__SPLIT_BLOCK;
    if (!ga2d__grow(&w->mem, (void **)&c->changed, &c->changed_capacity, (w->contact_used + 63) / 64,
                    sizeof *c->changed) ||
        !ga2d__grow(&w->mem, (void **)&c->tally, &c->tally_capacity, blocks, sizeof *c->tally)) {
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return 0;
    }
    ga2d__bits_zero(c->changed, w->contact_used);
    if (blocks > 0) memset(c->tally, 0, (size_t)blocks * sizeof *c->tally);
    w->counters.manifolds_carried = 0;
    return 1;
}

/* Book-keeping, in pool order, of the contacts the narrowphase flagged:
   touching begins and ends become events, a contact whose boxes parted is
   destroyed, and a touch wakes a sleeping island once every contact is
   updated (waking in the stage would let the pool's order decide which
   contacts of the woken island are updated in this step). */
static void ga2d__contact_changes(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int ci, used = w->contact_used, wakes = 0;
    for (ci = ga2d__next_bit(c->changed, 0, used); ci >= 0; ci = ga2d__next_bit(c->changed, ci + 1, used)) {
        ga2d__contact *ct = &w->contacts[ci];
        int f = ct->flags;
        if (f & GA2D__CONTACT_DISJOINT) {
            ct->flags = 0;
            if (ct->touching) ga2d__push_event(w, 1, ct);
            ga2d__destroy_contact(w, ci);
            continue;
        }
        if (f & GA2D__CONTACT_ENDED) {
            --w->touching_count;
            ga2d__push_event(w, 1, ct);
            memset(&ct->manifold, 0, sizeof ct->manifold); /* as ga2d__collide left it: no point */
            ct->manifold.normal = ct->end_normal;
        }
        if (f & GA2D__CONTACT_BEGAN) {
            ++w->touching_count;
            ga2d__push_event(w, 0, ct);
            /* for the touching list (out of memory: reported, and the
               list is walked anew) */
            if (w->touches_known &&
                !ga2d__grow(&w->mem, (void **)&w->began, &w->began_capacity, w->began_count + 1, sizeof *w->began)) {
                w->touches_known = 0;
                c->error = GA2D_ERR_OUT_OF_MEMORY;
            }
            if (w->touches_known) w->began[w->began_count++] = ci;
        }
        ct->flags = f & GA2D__CONTACT_WAKES;
        wakes += ct->flags != 0;
    }
    for (ci = ga2d__next_bit(c->changed, 0, used); ci >= 0 && wakes > 0; ci = ga2d__next_bit(c->changed, ci + 1, used)) {
        ga2d__contact *ct = &w->contacts[ci];
        if (ct->next_free != -2 || !ct->flags) continue;
        ct->flags = 0;
        --wakes;
        ga2d__wake(w, ct->a);
        ga2d__wake(w, ct->b);
    }
}

/* ========================================================== contact solver */
/* A contact point as the solver sees it: anchors from each body's centre
   of mass (world orientation, fixed for the step) and the accumulated
   impulses (the lanes find the masses: ga2d__wfind). */
typedef struct ga2d__cpoint {
    ga2d_vec ra, rb;
    ga2d_real separation;        /* at the step's start */
    ga2d_real normal_impulse, tangent_impulse;
    ga2d_real approach;          /* closing speed along the normal as the step began (hits only) */
} ga2d__cpoint;

/* A touching contact as the solver sees it for one step: its bodies, the
   normal, the materials, the inverse masses the solver may move (0 for a
   static, kinematic or sleeping side) and up to two points.  Joints will
   be constraints of their own kind beside it. */
struct ga2d__contact_constraint {
    int contact, a, b;           /* pool index, body slots */
    ga2d_vec normal;
    ga2d_vec d;                  /* B's centre less A's as the step began */
    ga2d_real friction, restitution;
    ga2d_real inv_ma, inv_ia, inv_mb, inv_ib;
    unsigned char count;         /* points */
    unsigned char hits;          /* a shape reports hits: the points' approach speeds are kept */
    unsigned char needs_extras;  /* round, conveyor or rolling: its group needs extras */
    unsigned char incident_b;    /* sharp sides: B's corners meet A's face (not A's B's) */
    unsigned char moves;         /* 1: it moves A, 2: B (ga2d__moves_a) */
    int lane;                    /* group * GA2D__LANES + lane in the lane solver */
    int seen;                    /* restitution: the impulses applied when it last looked */
    ga2d_real round_a, round_b;  /* the shapes' radii: their round parts (ga2d__point_now) */
    ga2d_real tangent_speed;     /* the surfaces' sliding along (ny, -nx): friction's target */
    ga2d_real rolling;           /* the largest torque impulse per unit normal impulse: c r */
    ga2d__cpoint p[2];
};


/* ------------------------------------------------------ the lane solver */
/* The velocity passes (warm start, solve, relax) run on groups of
   constraints that share no body they move, one constraint per lane, so
   each pass is GA2D__LANES independent sequential-impulse updates at once.  A
   group is solved as a whole and the groups one after the other: still
   Gauss-Seidel, in an order close to the canonical one.  Under gcc and
   clang a lane set is a vector of the compiler's (SSE2 on x86-64, NEON on
   arm64); elsewhere, or with GA2D_NO_SIMD, a struct of lanes.  Each lane
   computes exactly what the scalar code would, operation for operation, so
   both give the same bits (the determinism check builds both). */
/* 16 bytes, the width every 64-bit target has; 32 where the compiler is
   told of AVX (-mavx2, -march=native).  The width changes no bit of the
   results: constraints that share no moved body commute exactly, and the
   groups keep every body's own constraints in order. */
#if defined(__AVX__) && !defined(GA2D_NO_SIMD)
#define GA2D__BYTES 32
#else
#define GA2D__BYTES 16
#endif
#ifdef GA2D_DOUBLE
#define GA2D__LANES (GA2D__BYTES / 8)
#else
#define GA2D__LANES (GA2D__BYTES / 4)
#endif
#if (defined(__GNUC__) || defined(__clang__)) && !defined(GA2D_NO_SIMD)
/* aligned to one element, as a user's allocator owes no more */
#ifdef GA2D_DOUBLE
typedef double ga2d__w __attribute__((vector_size(GA2D__BYTES), aligned(8)));
typedef int64_t ga2d__wmask __attribute__((vector_size(GA2D__BYTES), aligned(8)));
#else
typedef float ga2d__w __attribute__((vector_size(GA2D__BYTES), aligned(4)));
typedef int32_t ga2d__wmask __attribute__((vector_size(GA2D__BYTES), aligned(4)));
#endif
#define GA2D__LANE(x, i) (x)[i]
#define GA2D__WINIT(...) {__VA_ARGS__}
static GA2D__HOT ga2d__w ga2d__wadd(ga2d__w a, ga2d__w b) { return a + b; }
static GA2D__HOT ga2d__w ga2d__wsub(ga2d__w a, ga2d__w b) { return a - b; }
static GA2D__HOT ga2d__w ga2d__wmul(ga2d__w a, ga2d__w b) { return a * b; }
static GA2D__HOT ga2d__w ga2d__wdiv(ga2d__w a, ga2d__w b) { return a / b; }
static GA2D__HOT ga2d__wmask ga2d__wgt(ga2d__w a, ga2d__w b) { return (ga2d__wmask)(a > b); }
static GA2D__HOT ga2d__wmask ga2d__wge(ga2d__w a, ga2d__w b) { return (ga2d__wmask)(a >= b); }
static GA2D__HOT ga2d__wmask ga2d__wand(ga2d__wmask a, ga2d__wmask b) { return a & b; }
static GA2D__HOT ga2d__w ga2d__wneg(ga2d__w a) { return -a; }
static GA2D__HOT ga2d__wmask ga2d__wne(ga2d__w a, ga2d__w b) { return (ga2d__wmask)(a != b); }
/* m ? a : b, lane by lane (m all ones or all zeros) */
static GA2D__HOT ga2d__w ga2d__wsel(ga2d__wmask m, ga2d__w a, ga2d__w b)
{
    return (ga2d__w)((m & (ga2d__wmask)a) | (~m & (ga2d__wmask)b));
}
#else
typedef struct ga2d__w { ga2d_real lane[GA2D__LANES]; } ga2d__w;
typedef struct ga2d__wmask { int lane[GA2D__LANES]; } ga2d__wmask;
#define GA2D__LANE(x, i) (x).lane[i]
#define GA2D__WINIT(...) {{__VA_ARGS__}}
#define GA2D__WOP(name, op)                                                                                            \
    static GA2D__HOT ga2d__w name(ga2d__w a, ga2d__w b)                                                               \
    {                                                                                                                  \
        int i;                                                                                                         \
        for (i = 0; i < GA2D__LANES; ++i) a.lane[i] = a.lane[i] op b.lane[i];                                                   \
        return a;                                                                                                      \
    }
GA2D__WOP(ga2d__wadd, +)
GA2D__WOP(ga2d__wsub, -)
GA2D__WOP(ga2d__wmul, *)
GA2D__WOP(ga2d__wdiv, /)
#undef GA2D__WOP
static GA2D__HOT ga2d__wmask ga2d__wgt(ga2d__w a, ga2d__w b)
{
    ga2d__wmask m;
    int i;
    for (i = 0; i < GA2D__LANES; ++i) m.lane[i] = a.lane[i] > b.lane[i];
    return m;
}
static GA2D__HOT ga2d__wmask ga2d__wge(ga2d__w a, ga2d__w b)
{
    ga2d__wmask m;
    int i;
    for (i = 0; i < GA2D__LANES; ++i) m.lane[i] = a.lane[i] >= b.lane[i];
    return m;
}
static GA2D__HOT ga2d__wmask ga2d__wand(ga2d__wmask a, ga2d__wmask b)
{
    int i;
    for (i = 0; i < GA2D__LANES; ++i) a.lane[i] = a.lane[i] && b.lane[i];
    return a;
}
static GA2D__HOT ga2d__w ga2d__wneg(ga2d__w a)
{
    int i;
    for (i = 0; i < GA2D__LANES; ++i) a.lane[i] = -a.lane[i];
    return a;
}
static GA2D__HOT ga2d__wmask ga2d__wne(ga2d__w a, ga2d__w b)
{
    ga2d__wmask m;
    int i;
    for (i = 0; i < GA2D__LANES; ++i) m.lane[i] = a.lane[i] != b.lane[i];
    return m;
}
static GA2D__HOT ga2d__w ga2d__wsel(ga2d__wmask m, ga2d__w a, ga2d__w b)
{
    int i;
    for (i = 0; i < GA2D__LANES; ++i) a.lane[i] = m.lane[i] ? a.lane[i] : b.lane[i];
    return a;
}
#endif

static GA2D__HOT ga2d__w ga2d__wsplat(ga2d_real x)
{
    ga2d__w r;
    int i;
    for (i = 0; i < GA2D__LANES; ++i) GA2D__LANE(r, i) = x;
    return r;
}

/* a x + b y: the dot product of the lanes' vectors (a, b) and (x, y) */
static GA2D__HOT ga2d__w ga2d__wdot(ga2d__w a, ga2d__w b, ga2d__w x, ga2d__w y)
{
    return ga2d__wadd(ga2d__wmul(a, x), ga2d__wmul(b, y));
}

/* A body as the passes see it: velocity, spin, and its motion since the
   step began (displacement dp, turn dq = q q0~).  Bodies that do not move
   keep v, w and a zero motion; one slot past the last body is a dummy for
   empty lanes.  Eight reals, so that the lanes' bodies load as whole rows
   and are transposed in registers (ga2d__wload). */
struct ga2d__sbody {
    ga2d_real vx, vy, w, pad, dpx, dpy, dqc, dqs;
};

/* The integration state of a moving body while the soft step's substeps
   integrate on the solver bodies (ga2d__compact_begin): what its kick and
   drift read beside the solver body, 40 bytes (float) where its own
   record is 232, so that the passes over the bodies stream two short
   arrays.  Without a force callback the kick is the same every substep:
   it is kept as h a, h alpha, found as ga2d__kick finds it. */
struct ga2d__kbody {
    ga2d_rotor q, q0;            /* its rotor now, and where the step began */
    ga2d_vec dv;                 /* h a (ga2d__acceleration) */
    ga2d_real dw;                /* h alpha */
    ga2d_real lin, ang;          /* the damping's factors 1/(1 + c h) (ga2d__damp), 1 without */
    int dynamic;
};

/* GA2D__LANES constraints, lane by lane: the bodies (the dummy slot in an empty
   lane), which of them the lane moves, its constraint's index, and the
   constraint's data.  A one-point contact's second point and an empty lane
   have zero masses, so their impulses stay zero. */
/* What only round shapes, conveyors and rolling resistance add to a
   group, kept in an array beside the groups (one per group, allocated only
   in a step that needs it) so that a polygon world's groups stay compact:
   the passes stream them. */
struct ga2d__group_extra {
    ga2d__w oax[2], oay[2], obx[2], oby[2]; /* round sides: what lies along n (ga2d__round_offset) */
    ga2d__w tw;             /* +-1/2 where one side is round: the point slides with it (ga2d__point_now) */
    ga2d__w tspeed;         /* the conveyor's tangent speed */
    ga2d__w rr, rmass, rimp; /* rolling resistance: rr = c r, rmass = 1/(iA + iB), rimp its impulse */
    ga2d__w npeak[2];       /* hit events: the largest normal impulse any pass of the step left */
};

/* A point's anchors now, relative to each centre. */
typedef struct ga2d__wanchors { ga2d__w ax, ay, bx, by; } ga2d__wanchors;

/* A point's arms there: each anchor's outer product with the normal n and
   the tangent t = (ny, -nx), r ^ u = rx uy - ry ux, the e12 part of r u.
   They are all a pass needs of the anchors: the bodies' spins move the
   point along u by w (rB ^ u) - w (rA ^ u), an impulse lambda u turns
   each by lambda (r ^ u) over its inertia, and the effective mass is
   1 / (mA^-1 + mB^-1 + IA^-1 (rA ^ u)^2 + IB^-1 (rB ^ u)^2). */
typedef struct ga2d__warms { ga2d__w na, nb, ta, tb; } ga2d__warms;

struct ga2d__group {
    int a[GA2D__LANES], b[GA2D__LANES];
    /* beside the body slots, which every pass reads first */
    unsigned char round;    /* a lane has a round shape: rax.. are core anchors, x->o.. what lies along n */
    unsigned char conveyor; /* a lane has a tangent speed (x->tspeed) */
    unsigned char rolling;  /* a lane has rolling resistance (x->rr, rmass, rimp) */
    unsigned char hits;     /* a lane reports hits (x->npeak) */
    unsigned char extras;   /* x's fields are written (ga2d__lane_extras) */
    int count;              /* lanes in use */
    ga2d__group_extra *x;   /* its extras while any lane of the step needs them, else NULL */
    int contact[GA2D__LANES];   /* the lane's contact (pool index), -1 in an empty lane */
    ga2d__wmask move_a, move_b; /* all ones where the lane moves A, B */
    ga2d__w nx, ny, friction, ima, iia, imb, iib;
    ga2d__w dx, dy;         /* centre B - centre A when the step began */
    ga2d__w rax[2], ray[2], rbx[2], rby[2];
    ga2d__w adjust[2];      /* start separation - (d0 + rB - rA).n */
    ga2d__w has2;           /* 1 where the lane has a second point, else 0 (an empty lane's
                               first point has zero masses of itself: no inverse mass) */
    ga2d__w nmass[2], tmass[2], nimp[2], timp[2];
    ga2d__w k12;            /* the points' normal coupling (ga2d__coupling) */
    ga2d__w share;          /* where the point lies from A's anchor to B's (ga2d__share) */
    /* found once per position of the bodies (ga2d__wfind), with the masses */
    ga2d__warms arm[2];     /* the points' arms there */
    ga2d__w sep[2];         /* their separations there */
};

/* A soft constraint seen by an implicit step (ga2d__make_soft). */

static ga2d__soft ga2d__make_soft(ga2d_real hertz, ga2d_real zeta, ga2d_real h)
{
    ga2d__soft s;
    ga2d_real omega = 2 * GA2D__PI * hertz, a1 = 2 * zeta + h * omega, a2 = h * omega * a1, a3 = 1 / (1 + a2);
    if (hertz == 0) {
        s.bias_rate = 0;
        s.mass_scale = 1;
        s.impulse_scale = 0;
        return s;
    }
    s.bias_rate = omega / a1;
    s.mass_scale = a2 * a3;
    s.impulse_scale = a3;
    return s;
}

/* The paper's impulse denominator for a direction d at anchors ra, rb:
   1/m_a + 1/m_b - (r_a ^ d)^2 / I_a - (r_b ^ d)^2 / I_b, where the
   bivector squares are negative ((w e12)^2 = -w^2), so with w = wedge:
   1/m_a + 1/m_b + w_a^2 / I_a + w_b^2 / I_b.  Its inverse is the mass the
   constraint sees along d. */
static ga2d_real ga2d__effective_mass(const ga2d__contact_constraint *c, ga2d_vec ra, ga2d_vec rb, ga2d_vec d)
{
    ga2d_real wa = ga2d_wedge(ra, d), wb = ga2d_wedge(rb, d);
    ga2d_real k = c->inv_ma + c->inv_mb + c->inv_ia * wa * wa + c->inv_ib * wb * wb;
    return k > 0 ? 1 / k : 0;
}

/* The off-diagonal entry of a two-point manifold's normal matrix K: how
   fast point 2's approach speed changes under a unit normal impulse at
   point 1 (and the reverse; K is symmetric).  The points share the pair's
   masses, so this is near the diagonal's size: why they are solved as a
   block (ga2d__wblock). */
static GA2D__HOT ga2d_real ga2d__coupling(const ga2d__contact_constraint *c, ga2d_vec ra1, ga2d_vec rb1, ga2d_vec ra2, ga2d_vec rb2)
{
    return c->inv_ma + c->inv_mb + c->inv_ia * ga2d_wedge(ra1, c->normal) * ga2d_wedge(ra2, c->normal) +
           c->inv_ib * ga2d_wedge(rb1, c->normal) * ga2d_wedge(rb2, c->normal);
}

/* Relative velocity of B's anchor point against A's: (vB + rB Omega_B) -
   (vA + rA Omega_A), with r Omega = w perp(r). */
static GA2D__HOT ga2d_vec ga2d__relative_velocity(const ga2d__body_sim *a, const ga2d__body_sim *b, ga2d_vec ra, ga2d_vec rb)
{
    ga2d_vec va = ga2d_vec_add(a->v, ga2d_vec_scale(ga2d_vec_perp(ra), a->w));
    ga2d_vec vb = ga2d_vec_add(b->v, ga2d_vec_scale(ga2d_vec_perp(rb), b->w));
    return ga2d_vec_sub(vb, va);
}

/* An impulse P at the anchors: B gains it, A loses it (dv = P/m,
   dOmega = I^-1 (r ^ P)).  A side the impulse cannot move (static or
   kinematic: zero inverse mass and inertia) is not written, so a NaN from
   a blown-up body stops there instead of reaching the ground (0 NaN = NaN)
   and from it every body resting on it. */
static GA2D__HOT void ga2d__apply_impulse(const ga2d__contact_constraint *c, ga2d__body_sim *a, ga2d__body_sim *b, ga2d_vec ra, ga2d_vec rb, ga2d_vec P)
{
    if (c->inv_ma != 0 || c->inv_ia != 0) {
        a->v = ga2d_vec_sub(a->v, ga2d_vec_scale(P, c->inv_ma));
        a->w -= c->inv_ia * ga2d_wedge(ra, P);
    }
    if (c->inv_mb != 0 || c->inv_ib != 0) {
        b->v = ga2d_vec_add(b->v, ga2d_vec_scale(P, c->inv_mb));
        b->w += c->inv_ib * ga2d_wedge(rb, P);
    }
}

/* A body's acceleration from gravity and the user's forces (0 for bodies
   that do not move under forces). */
static ga2d_vec ga2d__free_accel(const ga2d_world *w, const ga2d__body *b)
{
    if (b->type != GA2D_BODY_DYNAMIC || !b->awake) return ga2d_vec_make(0, 0);
    return ga2d_vec_add(ga2d_vec_scale(w->def.gravity, b->sim.gravity_scale), ga2d_vec_scale(b->sim.force, b->sim.inv_mass));
}

/* Whether a contact's bodies can move in the solver: an awake dynamic one. */
static int ga2d__solver_moves(const ga2d__body *b) { return b->type == GA2D_BODY_DYNAMIC && b->awake; }

/* The pre-solve callback's answer for a contact one of whose shapes asks
   for it (1 otherwise, or once the world is being destroyed from it).  It
   reads a copy of the manifold: its answer is its only effect, whatever
   it writes through the pointer (a count past 2, a NaN point). */
static int ga2d__pre_solve(ga2d_world *w, const ga2d__contact *ct)
{
    ga2d_manifold copy;
    if (!w->shapes[ct->shape_a].pre_solve_events && !w->shapes[ct->shape_b].pre_solve_events) return 1;
    if (w->destroy_pending) return 1;
    copy = ct->manifold;
    return w->def.pre_solve(ga2d__shape_id_of(w, ct->shape_a), ga2d__shape_id_of(w, ct->shape_b), &copy,
                            w->def.pre_solve_context) != 0;
}

/* What only round shapes, conveyors, rolling resistance and hit events
   need of a constraint (a polygon world's contacts never come here). */
static void ga2d__constraint_extras(ga2d_world *w, const ga2d__contact *ct, ga2d__contact_constraint *cc)
{
    const ga2d__shape *sa = &w->shapes[ct->shape_a], *sb = &w->shapes[ct->shape_b];
    ga2d_real rra = sa->rolling_resistance, rrb = sb->rolling_resistance;
    cc->round_a = sa->radius;
    cc->round_b = sb->radius;
    cc->hits = sa->hit_events || sb->hit_events;
    /* A's surface slides along t = (ny, -nx) at its speed, B's (whose
       outward normal is -n) along -t: B relative to A, s_a + s_b less */
    cc->tangent_speed = ga2d__saturate((sa->tangent_speed + sb->tangent_speed) * w->def.length_units_per_meter);
    /* rolling resistance: the larger coefficient at the rolling radius (a
       round side's; none between sharp shapes) */
    cc->rolling = ga2d__saturate((rra > rrb ? rra : rrb) * (cc->round_a > cc->round_b ? cc->round_a : cc->round_b));
    cc->needs_extras = cc->round_a != 0 || cc->round_b != 0 || cc->tangent_speed != 0 || cc->rolling != 0 || cc->hits;
}

/* Stage, over the constraints: each takes its contact's normal, material
   and points; static, kinematic and sleeping partners keep their
   velocities (inverse mass and inertia 0 here). */
static void ga2d__prepare_constraints(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    const ga2d__contact *contacts = w->contacts; /* in locals: see ga2d__gather */
    const ga2d__body *bodies = w->bodies;
    const int *order = c->order, warm = w->def.enable_warm_starting;
    int n, i;
    for (n = begin; n < end; ++n) {
        ga2d__contact_constraint *cc = &c->constraints[n];
        const ga2d__contact *ct = &contacts[order[n]];
        if (n + 2 * GA2D__PREFETCH_AHEAD < end) { /* that contact's record, then its bodies' once it is in */
            const ga2d__contact *far = &contacts[order[n + 2 * GA2D__PREFETCH_AHEAD]];
            GA2D__PREFETCH_CONTACT(far);
            GA2D__PREFETCH_READ(&far->manifold.points[0].separation);
            GA2D__PREFETCH_READ(&far->manifold.points[1].tangent_impulse);
        }
        if (n + GA2D__PREFETCH_AHEAD < end) {
            const ga2d__contact *near = &contacts[order[n + GA2D__PREFETCH_AHEAD]];
            GA2D__PREFETCH_READ(&bodies[near->a].sim.inv_mass);
            GA2D__PREFETCH_READ(&bodies[near->b].sim.inv_mass);
        }
        const ga2d__body *ba = &bodies[ct->a], *bb = &bodies[ct->b];
        const ga2d__body_sim *a = &ba->sim, *b = &bb->sim;
        int ma = ga2d__solver_moves(ba), mb = ga2d__solver_moves(bb);
        ga2d_vec ca, cb;
        cc->contact = order[n];
        cc->a = ct->a;
        cc->b = ct->b;
        cc->normal = ct->manifold.normal;
        cc->d = ga2d_vec_sub(b->center, a->center);
        cc->friction = ct->friction;
        cc->restitution = ct->restitution;
        cc->inv_ma = ma ? a->inv_mass : 0;
        cc->inv_ia = ma ? a->inv_inertia : 0;
        cc->inv_mb = mb ? b->inv_mass : 0;
        cc->inv_ib = mb ? b->inv_inertia : 0;
        cc->moves = (unsigned char)(((cc->inv_ma != 0) | (cc->inv_ia != 0)) | ((cc->inv_mb != 0) | (cc->inv_ib != 0)) << 1);
        cc->count = (unsigned char)ct->manifold.count;
        cc->round_a = cc->round_b = cc->tangent_speed = cc->rolling = 0;
        cc->hits = cc->needs_extras = 0;
        cc->incident_b = ct->manifold.count > 0 && !(ct->manifold.points[0].id & GA2D__FEATURE_FLIP);
        if (ct->extras) ga2d__constraint_extras(w, ct, cc);
        /* anchors from the centres, taken from the origin-relative ones so
           that no large coordinates are subtracted */
        ca = ga2d_rotate(a->q, a->local_center);
        cb = ga2d_rotate(b->q, b->local_center);
        for (i = 0; i < cc->count; ++i) {
            const ga2d_manifold_point *mp = &ct->manifold.points[i];
            ga2d__cpoint *p = &cc->p[i];
            p->ra = ga2d_vec_sub(mp->anchor_a, ca);
            p->rb = ga2d_vec_sub(mp->anchor_b, cb);
            p->separation = mp->separation;
            p->normal_impulse = warm ? mp->normal_impulse : 0;
            p->tangent_impulse = warm ? mp->tangent_impulse : 0;
            /* a hit is a point that starts pushing: one that carried an
               impulse from the last step is not hit again (a landing
               slowed early by the relax pass reported twice) */
            p->approach = cc->hits && mp->normal_impulse == 0
                              ? -ga2d_dot(ga2d__relative_velocity(a, b, p->ra, p->rb), cc->normal) : 0;
        }
    }
}

/* The constraints listed from `begin` on, prepared (on the workers, if
   `split`); out of memory, none is left. */
static void ga2d__prepare_listed(ga2d__step_context *c, int begin, int split)
{
    ga2d_world *w = c->world;
    if (!ga2d__grow(&w->mem, (void **)&c->constraints, &c->constraint_capacity, c->constraint_count,
                    sizeof *c->constraints)) {
        c->constraint_count = 0;
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return;
    }
    if (split) ga2d__run_split(c, ga2d__prepare_constraints, c->constraint_count);
    else ga2d__prepare_constraints(c, begin, c->constraint_count);
}

/* Book-keeping: a constraint for every touching contact with an awake
   dynamic body, in canonical order, not the pool's: body slots ascending,
   each body's own contacts (those where it is A) oldest first, as its
   list holds them; a contact the pre-solve callback turns down is left
   out.  Contacts elsewhere in the world, made
   and freed, shuffle the pool but not this order, so a scene's bits do
   not depend on them.  Oldest first matters: a pyramid's contacts, made
   in key order, are then solved bottom up.  The listed constraints are
   prepared (ga2d__prepare_constraints) a block at a time, while the
   contacts and bodies just read are still in cache: a world too large for
   the cache read them twice over when they were prepared after the whole
   list.  With workers, they are prepared after the whole list, on the
   workers.  Out of memory, the step reports it and solves no contact. */
#define GA2D__PREPARE_BLOCK 32 /* constraints listed, then prepared */

/* The touching list walked anew from the bodies' lists (their A sides):
   the canonical order by its definition.  0: out of memory. */
static int ga2d__walk_touches(ga2d_world *w)
{
    int slot, link;
    w->touch_count = w->began_count = 0;
    if (!ga2d__grow(&w->mem, (void **)&w->touches, &w->touch_capacity, w->contact_count, sizeof *w->touches)) return 0;
    for (slot = 0; slot < w->body_used; ++slot) {
        if (w->bodies[slot].type < 0) continue;
        for (link = ga2d__first_edge(w, slot); link >= 0; link = ga2d__next_edge(w, link)) {
            const ga2d__contact *ct = &w->contacts[link >> 1];
            ga2d__touch *t;
            if ((link & 1) != 0 || !ct->touching) continue;
            t = &w->touches[w->touch_count++];
            t->a = ct->a;
            t->contact = link >> 1;
            t->serial = ct->serial;
        }
    }
    return 1;
}

/* Whether touch t still names a live touching contact (not one that
   stopped, went, or whose slot a newer contact took). */
static int ga2d__touch_holds(const ga2d_world *w, const ga2d__touch *t)
{
    const ga2d__contact *ct = &w->contacts[t->contact];
    return ct->next_free == -2 && ct->serial == t->serial && ct->touching;
}

/* Canonical order: A's slot, then creation. */
static int ga2d__touch_before(const ga2d__touch *x, const ga2d__touch *y)
{
    return x->a != y->a ? x->a < y->a : x->serial < y->serial;
}
static int ga2d__cmp_touch(const void *x, const void *y)
{
    const ga2d__touch *p = (const ga2d__touch *)x, *q = (const ga2d__touch *)y;
    return ga2d__touch_before(p, q) ? -1 : (ga2d__touch_before(q, p) ? 1 : 0);
}

/* Stage, over the touching contacts (workers on hand, no pre-solve
   callback), before they are brought up to date: whether each still
   touches (ga2d__touch_holds), whether it is solved (a side the solver
   moves) and whether it bounces, for the update and the listing after
   (ga2d__update_touches). */
#define GA2D__TOUCH_SOLVED 1
#define GA2D__TOUCH_BOUNCY 2
#define GA2D__TOUCH_HOLDS 4
static unsigned char ga2d__touch_flags(const ga2d_world *w, const ga2d__contact *ct)
{
    if (!ga2d__solver_moves(&w->bodies[ct->a]) && !ga2d__solver_moves(&w->bodies[ct->b])) return 0;
    return (unsigned char)(GA2D__TOUCH_SOLVED | (ct->restitution != 0 ? GA2D__TOUCH_BOUNCY : 0));
}
static void ga2d__see_touches(ga2d__step_context *c, int begin, int end)
{
    const ga2d_world *w = c->world;
    int i;
    for (i = begin; i < end; ++i) {
        const ga2d__touch *t = &w->touches[i];
        if (i + 2 * GA2D__PREFETCH_AHEAD < end) /* that contact, then its bodies once it is in */
            GA2D__PREFETCH_CONTACT(&w->contacts[t[2 * GA2D__PREFETCH_AHEAD].contact]);
        if (i + GA2D__PREFETCH_AHEAD < end) {
            const ga2d__contact *near = &w->contacts[t[GA2D__PREFETCH_AHEAD].contact];
            GA2D__PREFETCH_READ(&w->bodies[near->a]);
            GA2D__PREFETCH_READ(&w->bodies[near->b]);
        }
        c->touch_seen[i] = ga2d__touch_holds(w, t)
                               ? (unsigned char)(GA2D__TOUCH_HOLDS | ga2d__touch_flags(w, &w->contacts[t->contact]))
                               : 0;
    }
}

/* Touch t into its place in the next list, and (listing) into the order
   when it is solved. */
static void ga2d__touch_put(ga2d_world *w, ga2d__step_context *list, const ga2d__touch *t, int flags, int *n)
{
    w->touches_next[(*n)++] = *t;
    if (!list || !(flags & GA2D__TOUCH_SOLVED)) return;
    list->order[list->constraint_count++] = t->contact;
    list->bouncy += (flags & GA2D__TOUCH_BOUNCY) != 0;
}
/* A touch that began since the last listing, so: its contact read here. */
static void ga2d__touch_put_new(ga2d_world *w, ga2d__step_context *list, const ga2d__touch *t, int *n)
{
    ga2d__touch_put(w, list, t, list ? ga2d__touch_flags(w, &w->contacts[t->contact]) : 0, n);
}

/* Book-keeping: the world's touching contacts in canonical order (by A's
   slot, then oldest first: each body's list holds its contacts so, and
   the A sides of the lists in slot order were walked for it each step).
   Kept from step to step: those that stopped touching or went are
   dropped and those that began (w->began, sorted) merged in, so a step
   reads only the touching ones, not every pair's record from both ends
   (the spinner's walk read 5.5 pairs per touching one, a cache miss
   each).  Walked anew when not known (a new or loaded world, compacted
   contacts, memory that ran out).  0: out of memory.
   `list` (workers on hand, no pre-solve callback): what is kept is found
   on the workers first (ga2d__see_touches), and the merge lists the
   solved ones into list's order as it goes, reading no contact but the
   new ones: the order the listing in ga2d__order_constraints makes. */
static int ga2d__update_touches(ga2d_world *w, ga2d__step_context *list)
{
    const unsigned char *seen = NULL;
    int i, j = 0, k, n = 0, fresh = 0;
    ga2d__touch *out;
    if (!w->touches_known) {
        w->touches_known = ga2d__walk_touches(w);
        if (!w->touches_known || !list) return w->touches_known;
    }
    if (!ga2d__grow(&w->mem, (void **)&w->touches_next, &w->touch_next_capacity, w->touch_count + w->began_count,
                    sizeof *w->touches_next)) {
        w->touches_known = 0;
        return 0;
    }
    if (list) {
        if (!ga2d__grow(&w->mem, (void **)&list->touch_seen, &list->touch_seen_capacity, w->touch_count,
                        sizeof *list->touch_seen))
            return 0;
        ga2d__run_split(list, ga2d__see_touches, w->touch_count);
        seen = list->touch_seen;
    }
    /* the new ones, still touching, sorted at the end of the next list's room */
    out = w->touches_next;
    for (k = 0; k < w->began_count; ++k) {
        const ga2d__contact *ct = &w->contacts[w->began[k]];
        ga2d__touch *t = &out[w->touch_count + fresh];
        if (ct->next_free != -2 || !ct->touching) continue;
        t->a = ct->a;
        t->contact = w->began[k];
        t->serial = ct->serial;
        ++fresh;
    }
    if (fresh > 1) qsort(out + w->touch_count, (size_t)fresh, sizeof *out, ga2d__cmp_touch);
    /* merged: the kept ones and the new, in order (a new one is never
       listed already: it did not touch at the last listing) */
    for (i = 0; i < w->touch_count; ++i) {
        const ga2d__touch *t = &w->touches[i];
        int flags;
        if (seen) {
            flags = seen[i];
        } else {
            if (i + GA2D__PREFETCH_AHEAD < w->touch_count) GA2D__PREFETCH_CONTACT(&w->contacts[t[GA2D__PREFETCH_AHEAD].contact]);
            flags = ga2d__touch_holds(w, t) ? GA2D__TOUCH_HOLDS : 0;
        }
        if (!(flags & GA2D__TOUCH_HOLDS)) continue;
        for (; j < fresh && ga2d__touch_before(&out[w->touch_count + j], t); ++j) ga2d__touch_put_new(w, list, &out[w->touch_count + j], &n);
        ga2d__touch_put(w, list, t, flags, &n);
    }
    for (; j < fresh; ++j) ga2d__touch_put_new(w, list, &out[w->touch_count + j], &n);
    ga2d__swap_arrays((void **)&w->touches, &w->touch_capacity, (void **)&w->touches_next, &w->touch_next_capacity);
    w->touch_count = n;
    w->began_count = 0;
    return 1;
}

static void ga2d__order_constraints(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int i, prepared = 0, listed = 0, bouncy = 0, split = w->def.worker_count > 1 && w->def.enqueue_task;
    int *order;
    c->constraint_count = c->bouncy = 0;
    /* room for every contact at once (each has at most one constraint);
       the order is kept apart from the constraints, so that listing it
       does not pass over their memory once more */
    if (!ga2d__grow(&w->mem, (void **)&c->order, &c->order_capacity, w->contact_count, sizeof *c->order) ||
        !ga2d__update_touches(w, split && !w->def.pre_solve ? c : NULL)) {
        c->constraint_count = 0;
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return;
    }
    if (split && !w->def.pre_solve) { /* listed as the touches were brought up to date */
        ga2d__prepare_listed(c, 0, 1);
        return;
    }
    order = c->order;
    /* counted in locals: the order's stores may alias c's fields */
    for (i = 0; i < w->touch_count; ++i) {
        const ga2d__contact *ct = &w->contacts[w->touches[i].contact];
        if (i + 2 * GA2D__PREFETCH_AHEAD < w->touch_count) /* that contact, then its bodies once it is in */
            GA2D__PREFETCH_CONTACT(&w->contacts[w->touches[i + 2 * GA2D__PREFETCH_AHEAD].contact]);
        if (i + GA2D__PREFETCH_AHEAD < w->touch_count) {
            const ga2d__contact *near = &w->contacts[w->touches[i + GA2D__PREFETCH_AHEAD].contact];
            GA2D__PREFETCH_READ(&w->bodies[near->a]);
            GA2D__PREFETCH_READ(&w->bodies[near->b]);
        }
        if (!ga2d__solver_moves(&w->bodies[ct->a]) && !ga2d__solver_moves(&w->bodies[ct->b])) continue;
        if (w->def.pre_solve && !ga2d__pre_solve(w, ct)) continue;
        order[listed++] = w->touches[i].contact;
        bouncy += ct->restitution != 0;
        if (split || listed - prepared < GA2D__PREPARE_BLOCK) continue;
        c->constraint_count = listed;
        ga2d__prepare_listed(c, prepared, 0);
        if (c->constraint_count == 0) return;
        prepared = listed;
    }
    c->constraint_count = listed;
    c->bouncy = bouncy;
    ga2d__prepare_listed(c, prepared, split);
}

/* Stage, over the moving bodies: where each was when the step began (the
   solver measures a point's current separation by how far its anchors
   have moved since). */
static void ga2d__remember_start(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        b->sim.center0 = b->sim.center;
        b->sim.dp = ga2d_vec_make(0, 0);
        b->sim.q0 = b->sim.q;
        b->sim.dq = ga2d_rotor_identity();
    }
}

/* Stage, over the moving bodies: each one's turn since the step began,
   once per solver pass rather than once per contact point. */
static void ga2d__refresh_turns(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        b->sim.dq = ga2d_rotor_mul(b->sim.q, ga2d_rotor_inverse(b->sim.q0));
    }
}

/* Point p now.  Each body carries its anchor by its motion since the step
   began (r -> r dq, dq = q q0~ refreshed per pass); the separation is the start separation plus how far
   B's anchor point moved away from A's along the normal; and the impulse
   acts at one point on the way between the two anchor points
   (ga2d__share), the one point the pair shares, so that the impulses -P
   on A and +P on B have no moment and
   angular momentum about any point is kept.  Anchors are returned relative
   to each centre, built from the centre-to-centre vector so that nothing
   large is subtracted.  A round shape's anchor is a core point and its
   radius along the normal: only the core point turns with the body (a
   rolling disc's contact stays at its bottom, where carrying it round
   would lift it by r (1 - cos) and let the disc sink). */
static GA2D__HOT ga2d_vec ga2d__round_offset(const ga2d__contact_constraint *c, const ga2d__cpoint *p, int side)
{
    /* the point lies midway between the surfaces: s/2 out of A's surface
       along n, and s/2 out of B's along -n; a surface lies its radius out
       of its core.  A sharp side's point turns with it whole. */
    ga2d_real rho = side ? c->round_b : c->round_a;
    if (rho == 0) return ga2d_vec_make(0, 0);
    return ga2d_vec_scale(c->normal, side ? -(rho + p->separation / 2) : rho + p->separation / 2);
}

/* Where on e (A's anchor to B's, both carried) the shared point lies:
   between sharp sides, at the incident side's anchor: the corner that
   meets the other's face, which slides along the face with its body (at
   the midpoint, the point lagged the corner by half the slide, and the
   relax pass's 2 x 2 block, its masses made at the step's start, left a
   sliding box a vertical speed and a spin that grew as v^2); where a side
   is round, midway, and along the surfaces the round side's (below). */
static GA2D__HOT ga2d_real ga2d__share(const ga2d__contact_constraint *c)
{
    if (c->round_a != 0 || c->round_b != 0) return GA2D__R(0.5);
    return c->incident_b ? 1 : 0;
}

static GA2D__HOT ga2d_real ga2d__point_now(const ga2d__contact_constraint *c, const ga2d__body_sim *a, const ga2d__body_sim *b,
                                 const ga2d__cpoint *p, ga2d_vec *ra, ga2d_vec *rb)
{
    ga2d_vec ra1, rb1;
    if (c->round_a != 0 || c->round_b != 0) {
        ga2d_vec oa = ga2d__round_offset(c, p, 0), ob = ga2d__round_offset(c, p, 1);
        ra1 = ga2d_vec_add(ga2d_rotate(a->dq, ga2d_vec_sub(p->ra, oa)), oa);
        rb1 = ga2d_vec_add(ga2d_rotate(b->dq, ga2d_vec_sub(p->rb, ob)), ob);
    } else {
        ra1 = ga2d_rotate(a->dq, p->ra);
        rb1 = ga2d_rotate(b->dq, p->rb);
    }
    {
    ga2d_vec d = ga2d_vec_sub(b->center, a->center);
    ga2d_vec da = ga2d_vec_add(ga2d_vec_sub(a->center, a->center0), ga2d_vec_sub(ra1, p->ra));
    ga2d_vec db = ga2d_vec_add(ga2d_vec_sub(b->center, b->center0), ga2d_vec_sub(rb1, p->rb));
    ga2d_vec e = ga2d_vec_sub(ga2d_vec_add(d, rb1), ra1);
    *ra = ga2d_vec_add(ra1, ga2d_vec_scale(e, ga2d__share(c)));
    if ((c->round_a != 0) != (c->round_b != 0)) {
        /* one side round: along the surfaces the point is the round
           side's (a disc's impulses pass through its bottom, where the
           midpoint of anchors sliding apart would lag and brake it) */
        ga2d_vec et = ga2d_vec_sub(e, ga2d_vec_scale(c->normal, ga2d_dot(e, c->normal)));
        *ra = ga2d_vec_add(*ra, ga2d_vec_scale(et, c->round_b != 0 ? GA2D__R(0.5) : GA2D__R(-0.5)));
    }
    *rb = ga2d_vec_sub(*ra, d);
    return p->separation + ga2d_dot(ga2d_vec_sub(db, da), c->normal);
    }
}

/* The lanes' bodies in registers. */
typedef struct ga2d__wbody { ga2d__w vx, vy, w, pad, dpx, dpy, qc, qs; } ga2d__wbody;

/* The lanes' bodies as whole rows: lane l's body, GA2D__LANES reals at a
   time, is row l of a square block; transposed in registers, row k holds
   field k of every lane.  Gathering field by field instead costs a scalar
   load and an insert per lane and field.  It
   needs the compiler's vector shuffle: clang's and gcc 12's
   __builtin_shufflevector, or older gcc's __builtin_shuffle in C (its
   index vector is a compound literal, which C++ lacks). */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(GA2D_NO_SIMD)
#if defined(__clang__) || __GNUC__ >= 12
#define GA2D__SHUF(a, b, ...) __builtin_shufflevector(a, b, __VA_ARGS__)
#elif !defined(__cplusplus)
#define GA2D__SHUF(a, b, ...) __builtin_shuffle(a, b, (ga2d__wmask){__VA_ARGS__})
#endif
#endif
/* With AVX (32-byte vectors: 8 float lanes, 4 double) a square
   transpose would cross the register's 16-byte halves, each crossing a
   slow shuffle.  So a row holds two bodies' reals instead, lane l's in the
   low half and lane l + E's in the high half (E = GA2D__LANES / 2, the
   lanes, and the reals, a half holds; joined by __builtin_shufflevector:
   clang, gcc 12), and the rows are transposed within the halves, where
   every shuffle is cheap.  Gathered field by field instead, the float AVX
   build stepped joint_grid 1.35x and the pyramids 1.15x slower; the
   square transpose made the double AVX build slower than double SSE2. */
#if defined(GA2D__SHUF) && (GA2D__BYTES == 16 || defined(__clang__) || __GNUC__ >= 12)
#if GA2D__BYTES == 32
#define GA2D__E (GA2D__LANES / 2)
typedef ga2d_real ga2d__whalf __attribute__((vector_size(16), aligned(sizeof(ga2d_real))));
static GA2D__HOT ga2d__w ga2d__wrow(const ga2d_real *lo, const ga2d_real *hi)
{
    ga2d__whalf l, h;
    memcpy(&l, lo, sizeof l);
    memcpy(&h, hi, sizeof h);
#ifdef GA2D_DOUBLE
    return __builtin_shufflevector(l, h, 0, 1, 2, 3);
#else
    return __builtin_shufflevector(l, h, 0, 1, 2, 3, 4, 5, 6, 7);
#endif
}
#else
static GA2D__HOT ga2d__w ga2d__wrow(const ga2d_real *p)
{
    ga2d__w r;
    memcpy(&r, p, sizeof r);
    return r;
}
#endif

/* r[0 .. GA2D__LANES-1] transposed in place (2 or 4 lanes in 16 bytes; in
   32, the first 4 rows, half by half).  Written out, as are the row loops
   below: gcc -O2 does not unroll them, and rolled they keep the rows in
   memory. */
static GA2D__HOT void ga2d__wtranspose(ga2d__w *r)
{
#if GA2D__LANES == 2
    ga2d__w t0 = GA2D__SHUF(r[0], r[1], 0, 2), t1 = GA2D__SHUF(r[0], r[1], 1, 3);
    r[0] = t0;
    r[1] = t1;
#elif GA2D__LANES == 8
    ga2d__w t0 = GA2D__SHUF(r[0], r[1], 0, 8, 1, 9, 4, 12, 5, 13), t1 = GA2D__SHUF(r[2], r[3], 0, 8, 1, 9, 4, 12, 5, 13);
    ga2d__w t2 = GA2D__SHUF(r[0], r[1], 2, 10, 3, 11, 6, 14, 7, 15), t3 = GA2D__SHUF(r[2], r[3], 2, 10, 3, 11, 6, 14, 7, 15);
    r[0] = GA2D__SHUF(t0, t1, 0, 1, 8, 9, 4, 5, 12, 13);
    r[1] = GA2D__SHUF(t0, t1, 2, 3, 10, 11, 6, 7, 14, 15);
    r[2] = GA2D__SHUF(t2, t3, 0, 1, 8, 9, 4, 5, 12, 13);
    r[3] = GA2D__SHUF(t2, t3, 2, 3, 10, 11, 6, 7, 14, 15);
#elif GA2D__BYTES == 32 /* 4 doubles: rows 0, 1 hold fields 0, 1; rows 2, 3 fields 2, 3 */
    ga2d__w t0 = GA2D__SHUF(r[0], r[1], 0, 4, 2, 6), t1 = GA2D__SHUF(r[0], r[1], 1, 5, 3, 7);
    ga2d__w t2 = GA2D__SHUF(r[2], r[3], 0, 4, 2, 6), t3 = GA2D__SHUF(r[2], r[3], 1, 5, 3, 7);
    r[0] = t0;
    r[1] = t1;
    r[2] = t2;
    r[3] = t3;
#else
    ga2d__w t0 = GA2D__SHUF(r[0], r[1], 0, 4, 1, 5), t1 = GA2D__SHUF(r[2], r[3], 0, 4, 1, 5);
    ga2d__w t2 = GA2D__SHUF(r[0], r[1], 2, 6, 3, 7), t3 = GA2D__SHUF(r[2], r[3], 2, 6, 3, 7);
    r[0] = GA2D__SHUF(t0, t1, 0, 1, 4, 5);
    r[1] = GA2D__SHUF(t0, t1, 2, 3, 6, 7);
    r[2] = GA2D__SHUF(t2, t3, 0, 1, 4, 5);
    r[3] = GA2D__SHUF(t2, t3, 2, 3, 6, 7);
#endif
}

/* Rows j .. j + GA2D__LANES - 1 of the block: lane l's body from real j
   on, into f[j + l] (load), or back where the lane moves it (store): a
   body a lane does not move may be another lane's, in a group another
   worker solves at the same time, and is not written.  In 32 bytes, rows
   j .. j + 3: row l holds lanes l % E and l % E + E, from real j + l / E E
   on. */
#if GA2D__BYTES == 32
#define GA2D__AT(l, h) (&s[slot[(l) % GA2D__E + (h) * GA2D__E]].vx + j + (l) / GA2D__E * GA2D__E)
#define GA2D__ROW(l) f[j + (l)] = ga2d__wrow(GA2D__AT(l, 0), GA2D__AT(l, 1))
#define GA2D__HALF(l, h)                                                                                               \
    if (GA2D__LANE(m, (l) % GA2D__E + (h) * GA2D__E))                                                                  \
    memcpy(GA2D__AT(l, h), (char *)&f[j + (l)] + (h) * sizeof(ga2d__whalf), sizeof(ga2d__whalf))
#define GA2D__PUT(l) GA2D__HALF(l, 0); GA2D__HALF(l, 1)
#else
#define GA2D__ROW(l) f[j + (l)] = ga2d__wrow(&s[slot[l]].vx + j)
#define GA2D__PUT(l) if (GA2D__LANE(m, l)) memcpy(&s[slot[l]].vx + j, &f[j + (l)], sizeof f[0])
#endif
#if GA2D__LANES == 2
#define GA2D__ROWS(op) op(0); op(1)
#else
#define GA2D__ROWS(op) op(0); op(1); op(2); op(3)
#endif

static GA2D__HOT void ga2d__wload_block(const ga2d__sbody *s, const int *slot, int j, ga2d__w *f)
{
    GA2D__ROWS(GA2D__ROW);
    ga2d__wtranspose(&f[j]);
}

static GA2D__HOT void ga2d__wstore_block(ga2d__sbody *s, const int *slot, ga2d__wmask m, int j, ga2d__w *f)
{
    ga2d__wtranspose(&f[j]);
    GA2D__ROWS(GA2D__PUT);
}

/* The eight fields of the lanes' bodies, block by block of rows; or
   (`motion` 0) the first four only, the velocities: a pass that finds the
   anchors kept (ga2d__wfind) reads no motion. */
static GA2D__HOT void ga2d__wload(const ga2d__sbody *s, const int *slot, ga2d__wbody *o, int motion)
{
    ga2d__w f[8];
    ga2d__wload_block(s, slot, 0, f);
#if GA2D__LANES == 2
    ga2d__wload_block(s, slot, 2, f);
#endif
    o->vx = f[0];
    o->vy = f[1];
    o->w = f[2];
    o->pad = f[3];
    if (!motion) return;
    ga2d__wload_block(s, slot, 4, f);
#if GA2D__LANES == 2
    ga2d__wload_block(s, slot, 6, f);
#endif
    o->dpx = f[4];
    o->dpy = f[5];
    o->qc = f[6];
    o->qs = f[7];
}

/* Velocities back where mask m is set (the bodies the lanes move); a
   body a lane does not move may be another lane's too, and keeps its own.
   Only the rows that hold v and w are written (the row's fourth real, the
   pad, as it was loaded). */
static GA2D__HOT void ga2d__wstore(ga2d__sbody *s, const int *slot, ga2d__wmask m, const ga2d__wbody *o)
{
    ga2d__w f[8];
    f[0] = o->vx;
    f[1] = o->vy;
    f[2] = o->w;
    f[3] = o->pad;
    ga2d__wstore_block(s, slot, m, 0, f);
#if GA2D__LANES == 2
    ga2d__wstore_block(s, slot, m, 2, f);
#endif
}
#undef GA2D__ROW
#undef GA2D__PUT
#undef GA2D__HALF
#undef GA2D__AT
#undef GA2D__E
#undef GA2D__ROWS
#else
/* Field by field, each vector made whole at once (the compiler then sees
   every lane written). */
#define GA2D__G(s, slot, f, i) (s)[(slot)[i]].f
#if GA2D__LANES == 8
#define GA2D__GATHER(s, slot, f)                                                                                       \
    ga2d__wset(GA2D__G(s, slot, f, 0), GA2D__G(s, slot, f, 1), GA2D__G(s, slot, f, 2), GA2D__G(s, slot, f, 3),          \
               GA2D__G(s, slot, f, 4), GA2D__G(s, slot, f, 5), GA2D__G(s, slot, f, 6), GA2D__G(s, slot, f, 7))
static GA2D__HOT ga2d__w ga2d__wset(ga2d_real a, ga2d_real b, ga2d_real c, ga2d_real d, ga2d_real e, ga2d_real f,
                                    ga2d_real g, ga2d_real h)
{
    ga2d__w r = GA2D__WINIT(a, b, c, d, e, f, g, h);
    return r;
}
#elif GA2D__LANES == 4
#define GA2D__GATHER(s, slot, f)                                                                                       \
    ga2d__wset(GA2D__G(s, slot, f, 0), GA2D__G(s, slot, f, 1), GA2D__G(s, slot, f, 2), GA2D__G(s, slot, f, 3))
static GA2D__HOT ga2d__w ga2d__wset(ga2d_real a, ga2d_real b, ga2d_real c, ga2d_real d)
{
    ga2d__w r = GA2D__WINIT(a, b, c, d);
    return r;
}
#else
#define GA2D__GATHER(s, slot, f) ga2d__wset(GA2D__G(s, slot, f, 0), GA2D__G(s, slot, f, 1))
static GA2D__HOT ga2d__w ga2d__wset(ga2d_real a, ga2d_real b)
{
    ga2d__w r = GA2D__WINIT(a, b);
    return r;
}
#endif

static GA2D__HOT void ga2d__wload(const ga2d__sbody *s, const int *slot, ga2d__wbody *o, int motion)
{
    o->vx = GA2D__GATHER(s, slot, vx);
    o->vy = GA2D__GATHER(s, slot, vy);
    o->w = GA2D__GATHER(s, slot, w);
    o->pad = GA2D__GATHER(s, slot, pad);
    if (!motion) return;
    o->dpx = GA2D__GATHER(s, slot, dpx);
    o->dpy = GA2D__GATHER(s, slot, dpy);
    o->qc = GA2D__GATHER(s, slot, dqc);
    o->qs = GA2D__GATHER(s, slot, dqs);
}

/* Velocities back, for the bodies the lanes move (mask m); a body a lane
   does not move may be another lane's too, and keeps its own. */
static GA2D__HOT void ga2d__wstore(ga2d__sbody *s, const int *slot, ga2d__wmask m, const ga2d__wbody *o)
{
    int l;
    for (l = 0; l < GA2D__LANES; ++l) {
        ga2d__sbody *b = &s[slot[l]];
        if (!GA2D__LANE(m, l)) continue;
        b->vx = GA2D__LANE(o->vx, l);
        b->vy = GA2D__LANE(o->vy, l);
        b->w = GA2D__LANE(o->w, l);
    }
}
#endif

/* ga2d__point_now for the lanes (its comment says why), rearranged: with
   e = d + rB' - rA' (d the centres' offset now, r' the anchors turned by
   the bodies' turns so far), the anchor points have moved apart by
   e - (d0 + rB - rA), so the separation now is that along n plus the
   start separation; the second term is constant over the step and kept
   as `adjust`.  The anchors now are the shared point's: rA' + share e
   and that less d. */
static GA2D__HOT ga2d__w ga2d__wpoint_now(const ga2d__group *g, int k, const ga2d__wbody *A, const ga2d__wbody *B,
                                          ga2d__wanchors *r, int extras)
{
    ga2d__w ra1x = ga2d__wsub(ga2d__wmul(A->qc, g->rax[k]), ga2d__wmul(A->qs, g->ray[k]));
    ga2d__w ra1y = ga2d__wadd(ga2d__wmul(A->qs, g->rax[k]), ga2d__wmul(A->qc, g->ray[k]));
    ga2d__w rb1x = ga2d__wsub(ga2d__wmul(B->qc, g->rbx[k]), ga2d__wmul(B->qs, g->rby[k]));
    ga2d__w rb1y = ga2d__wadd(ga2d__wmul(B->qs, g->rbx[k]), ga2d__wmul(B->qc, g->rby[k]));
    ga2d__w dx = ga2d__wadd(g->dx, ga2d__wsub(B->dpx, A->dpx)), dy = ga2d__wadd(g->dy, ga2d__wsub(B->dpy, A->dpy));
    if (extras && g->round) { /* the radii along n, which do not turn (ga2d__point_now) */
        ra1x = ga2d__wadd(ra1x, g->x->oax[k]);
        ra1y = ga2d__wadd(ra1y, g->x->oay[k]);
        rb1x = ga2d__wadd(rb1x, g->x->obx[k]);
        rb1y = ga2d__wadd(rb1y, g->x->oby[k]);
    }
    ga2d__w ex = ga2d__wsub(ga2d__wadd(dx, rb1x), ra1x), ey = ga2d__wsub(ga2d__wadd(dy, rb1y), ra1y);
    r->ax = ga2d__wadd(ra1x, ga2d__wmul(ex, g->share));
    r->ay = ga2d__wadd(ra1y, ga2d__wmul(ey, g->share));
    if (extras && g->round) { /* along the surfaces, the round side's point */
        ga2d__w en = ga2d__wdot(ex, ey, g->nx, g->ny);
        r->ax = ga2d__wadd(r->ax, ga2d__wmul(g->x->tw, ga2d__wsub(ex, ga2d__wmul(en, g->nx))));
        r->ay = ga2d__wadd(r->ay, ga2d__wmul(g->x->tw, ga2d__wsub(ey, ga2d__wmul(en, g->ny))));
    }
    r->bx = ga2d__wsub(r->ax, dx);
    r->by = ga2d__wsub(r->ay, dy);
    return ga2d__wadd(g->adjust[k], ga2d__wdot(ex, ey, g->nx, g->ny));
}

/* r ^ u = rx uy - ry ux, lane by lane (the arm of u at r) */
static GA2D__HOT ga2d__w ga2d__wwedge(ga2d__w rx, ga2d__w ry, ga2d__w ux, ga2d__w uy)
{
    return ga2d__wsub(ga2d__wmul(rx, uy), ga2d__wmul(ry, ux));
}

/* The relative velocity of a point's anchors along u, as
   ga2d__relative_velocity, from the centres' along u (`lin`, the same for
   both points) and the arms of u there (a, b). */
static GA2D__HOT ga2d__w ga2d__wrelative(const ga2d__wbody *A, const ga2d__wbody *B, ga2d__w lin, ga2d__w a, ga2d__w b)
{
    return ga2d__wsub(ga2d__wadd(lin, ga2d__wmul(B->w, b)), ga2d__wmul(A->w, a));
}

/* The impulse (px, py) through both centres and the moments ma, mb (the
   impulses' arms times their sizes, summed over the points), as
   ga2d__apply_impulse. */
static GA2D__HOT void ga2d__wapply(const ga2d__group *g, ga2d__wbody *A, ga2d__wbody *B, ga2d__w px, ga2d__w py,
                                   ga2d__w ma, ga2d__w mb)
{
    A->vx = ga2d__wsub(A->vx, ga2d__wmul(px, g->ima));
    A->vy = ga2d__wsub(A->vy, ga2d__wmul(py, g->ima));
    A->w = ga2d__wsub(A->w, ga2d__wmul(g->iia, ma));
    B->vx = ga2d__wadd(B->vx, ga2d__wmul(px, g->imb));
    B->vy = ga2d__wadd(B->vy, ga2d__wmul(py, g->imb));
    B->w = ga2d__wadd(B->w, ga2d__wmul(g->iib, mb));
}

/* ga2d__effective_mass for the lanes, from the arms a, b of the
   direction at the anchors; zero where the point is absent (a second point
   by has2; an empty lane's first has no inverse mass). */
static GA2D__HOT ga2d__w ga2d__weffective_mass(const ga2d__group *g, int k, ga2d__w a, ga2d__w b)
{
    ga2d__w kk = ga2d__wadd(ga2d__wadd(ga2d__wadd(g->ima, g->imb), ga2d__wmul(ga2d__wmul(g->iia, a), a)),
                            ga2d__wmul(ga2d__wmul(g->iib, b), b));
    ga2d__w zero = ga2d__wsplat(0), one = ga2d__wsplat(1);
    ga2d__wmask pos = ga2d__wgt(kk, zero);
    ga2d__w m = ga2d__wsel(pos, ga2d__wdiv(one, ga2d__wsel(pos, kk, one)), zero);
    return k == 0 ? m : ga2d__wmul(m, g->has2);
}

/* x clamped to [lo, hi] lane by lane, as the scalar x > hi ? hi : (x < lo ? lo : x) */
static GA2D__HOT ga2d__w ga2d__wclamp(ga2d__w x, ga2d__w lo, ga2d__w hi)
{
    return ga2d__wsel(ga2d__wgt(x, hi), hi, ga2d__wsel(ga2d__wgt(lo, x), lo, x));
}

/* ga2d__coupling for the lanes, from the points' normal arms (zero where
   a point is absent). */
static GA2D__HOT ga2d__w ga2d__wcoupling(const ga2d__group *g)
{
    const ga2d__warms *r = g->arm;
    ga2d__w k = ga2d__wadd(ga2d__wadd(ga2d__wadd(g->ima, g->imb), ga2d__wmul(ga2d__wmul(g->iia, r[0].na), r[1].na)),
                           ga2d__wmul(ga2d__wmul(g->iib, r[0].nb), r[1].nb));
    return ga2d__wmul(k, g->has2);
}

/* What depends on the bodies' positions alone, found once per position
   (the first of the warm start and the passes to run there, while
   c->masses_stale) and kept in the group: each point's anchors and
   separation (ga2d__wpoint_now), its normal and tangent masses (the
   tangent's only with friction) and their coupling.  The warm start and a
   soft pass then run on the velocities alone, and the relax pass after the
   drift finds them for the next substep's warm start and soft pass.  A
   run over the same positions finds the same bits, so keeping them
   changes none. */
static GA2D__HOT void ga2d__wfind(ga2d__group *g, const ga2d__wbody *A, const ga2d__wbody *B, int friction, int extras)
{
    /* the two points side by side, written out: as a loop (gcc -O2 does
       not unroll it) each point's divisions waited on the last's, and
       large_pyramid stepped 4-5 % slower */
    ga2d__w tx = g->ny, ty = ga2d__wsub(ga2d__wsplat(0), g->nx);
    ga2d__wanchors r0, r1;
    ga2d__warms *m = g->arm;
    g->sep[0] = ga2d__wpoint_now(g, 0, A, B, &r0, extras);
    g->sep[1] = ga2d__wpoint_now(g, 1, A, B, &r1, extras);
    m[0].na = ga2d__wwedge(r0.ax, r0.ay, g->nx, g->ny);
    m[0].nb = ga2d__wwedge(r0.bx, r0.by, g->nx, g->ny);
    m[1].na = ga2d__wwedge(r1.ax, r1.ay, g->nx, g->ny);
    m[1].nb = ga2d__wwedge(r1.bx, r1.by, g->nx, g->ny);
    m[0].ta = ga2d__wwedge(r0.ax, r0.ay, tx, ty);
    m[0].tb = ga2d__wwedge(r0.bx, r0.by, tx, ty);
    m[1].ta = ga2d__wwedge(r1.ax, r1.ay, tx, ty);
    m[1].tb = ga2d__wwedge(r1.bx, r1.by, tx, ty);
    g->nmass[0] = ga2d__weffective_mass(g, 0, m[0].na, m[0].nb);
    g->nmass[1] = ga2d__weffective_mass(g, 1, m[1].na, m[1].nb);
    if (friction) {
        g->tmass[0] = ga2d__weffective_mass(g, 0, m[0].ta, m[0].tb);
        g->tmass[1] = ga2d__weffective_mass(g, 1, m[1].ta, m[1].tb);
    }
    g->k12 = ga2d__wcoupling(g);
}

/* The two normal points of each lane solved together, as the linear
   complementarity problem they are: accumulated impulses x = x0 + lambda
   >= 0, and where x_k = 0 the point separates (its speed, bias included,
   >= 0).  Sequential impulses would give the point solved first more than
   its share and turn the pair, every pass the same way: a large pyramid
   sheared by metres in 500 steps.  Each row is divided by its own
   diagonal (with the soft scaling, inv_a = mass_scale / K_kk), so
   `own` is the point's update alone and p_k = inv_a_k K12 its coupling:
       lambda_1 + p_1 lambda_2 = own_1,   p_2 lambda_1 + lambda_2 = own_2.
   The cases in order of preference: both pushing; one alone; neither.  p_1
   p_2 < 1 (K is positive definite and softness only adds to its
   diagonal); both pushing is taken only while 1 - p_1 p_2 is not tiny
   (points nearly one point), and if rounding leaves no case valid, point
   1 alone, clamped.  A lane with one point has K12 = 0 and nmass_2 = 0,
   so it reduces to the one-point update. */
static GA2D__HOT void ga2d__wblock(const ga2d__group *g, const ga2d__w *inv_a, const ga2d__w *own, ga2d__w *lambda)
{
    const ga2d__w zero = ga2d__wsplat(0), one = ga2d__wsplat(1), tiny = ga2d__wsplat(GA2D__R(1e-3));
    ga2d__w p1 = ga2d__wmul(inv_a[0], g->k12), p2 = ga2d__wmul(inv_a[1], g->k12);
    ga2d__w x01 = g->nimp[0], x02 = g->nimp[1];
    ga2d__w det = ga2d__wsub(one, ga2d__wmul(p1, p2));
    ga2d__wmask solid = ga2d__wgt(det, tiny);
    ga2d__w inv_det = ga2d__wdiv(one, ga2d__wsel(solid, det, one));
    /* both */
    ga2d__w b1 = ga2d__wmul(ga2d__wsub(own[0], ga2d__wmul(p1, own[1])), inv_det);
    ga2d__w b2 = ga2d__wmul(ga2d__wsub(own[1], ga2d__wmul(p2, own[0])), inv_det);
    ga2d__wmask both = ga2d__wand(solid, ga2d__wand(ga2d__wge(ga2d__wadd(x01, b1), zero), ga2d__wge(ga2d__wadd(x02, b2), zero)));
    /* point 1 alone (x2 = 0) */
    ga2d__w o1 = ga2d__wadd(own[0], ga2d__wmul(p1, x02));
    ga2d__wmask only1 = ga2d__wand(ga2d__wge(ga2d__wadd(x01, o1), zero),
                                   ga2d__wge(ga2d__wsub(ga2d__wmul(p2, o1), ga2d__wadd(x02, own[1])), zero));
    /* point 2 alone (x1 = 0) */
    ga2d__w o2 = ga2d__wadd(own[1], ga2d__wmul(p2, x01));
    ga2d__wmask only2 = ga2d__wand(ga2d__wge(ga2d__wadd(x02, o2), zero),
                                   ga2d__wge(ga2d__wsub(ga2d__wmul(p1, o2), ga2d__wadd(x01, own[0])), zero));
    /* neither; else point 1 alone, clamped */
    ga2d__wmask none = ga2d__wand(ga2d__wge(ga2d__wsub(zero, ga2d__wadd(ga2d__wmul(p1, x02), ga2d__wadd(x01, own[0]))), zero),
                                  ga2d__wge(ga2d__wsub(zero, ga2d__wadd(ga2d__wmul(p2, x01), ga2d__wadd(x02, own[1]))), zero));
    ga2d__w l1 = ga2d__wsel(ga2d__wgt(ga2d__wadd(x01, o1), zero), o1, ga2d__wsub(zero, x01));
    ga2d__w l2 = ga2d__wsub(zero, x02);
    l1 = ga2d__wsel(none, ga2d__wsub(zero, x01), l1);
    l1 = ga2d__wsel(only2, ga2d__wsub(zero, x01), l1);
    l2 = ga2d__wsel(only2, o2, l2);
    l1 = ga2d__wsel(only1, o1, l1);
    l2 = ga2d__wsel(only1, ga2d__wsub(zero, x02), l2);
    lambda[0] = ga2d__wsel(both, b1, l1);
    lambda[1] = ga2d__wsel(both, b2, l2);
}

/* Where the colour of group gi ends, within a run of groups that ends
   at `end`: the groups up to there move no body in common.  An overflow
   group's ends where it begins (its next may move the same body). */
static int ga2d__colour_end(const ga2d__step_context *c, int gi, int end)
{
    int k = 0;
    while (k < c->colour_count && c->colour_start[k + 1] <= gi) ++k;
    if (k == c->colour_count) return gi + 1;
    return c->colour_start[k + 1] < end ? c->colour_start[k + 1] : end;
}

/* One group's accumulated impulses applied again at its anchors now
   (`extras` as in ga2d__solve_group; `find`, the anchors are found here
   first: ga2d__wfind). */
static GA2D__HOT void ga2d__warm_group(ga2d__step_context *c, ga2d__group *g, int extras, int find, int friction)
{
    ga2d__wbody A, B;
    ga2d__w n, t, ma, mb;
    int k;
    ga2d__wload(c->sbodies, g->a, &A, find);
    ga2d__wload(c->sbodies, g->b, &B, find);
    if (find) ga2d__wfind(g, &A, &B, friction, extras);
    /* both points' impulses at once: their sums along n and the tangent
       (ny, -nx) through the centres, and their moments */
    n = ga2d__wadd(g->nimp[0], g->nimp[1]);
    t = ga2d__wadd(g->timp[0], g->timp[1]);
    ma = mb = ga2d__wsplat(0);
    for (k = 0; k < 2; ++k) {
        const ga2d__warms *m = &g->arm[k];
        ma = ga2d__wadd(ma, ga2d__wadd(ga2d__wmul(m->na, g->nimp[k]), ga2d__wmul(m->ta, g->timp[k])));
        mb = ga2d__wadd(mb, ga2d__wadd(ga2d__wmul(m->nb, g->nimp[k]), ga2d__wmul(m->tb, g->timp[k])));
    }
    ga2d__wapply(g, &A, &B, ga2d__wadd(ga2d__wmul(g->nx, n), ga2d__wmul(g->ny, t)),
                 ga2d__wsub(ga2d__wmul(g->ny, n), ga2d__wmul(g->nx, t)), ma, mb);
    if (extras && g->rolling) { /* the rolling resistance's, as the points' */
        A.w = ga2d__wsub(A.w, ga2d__wmul(g->iia, g->x->rimp));
        B.w = ga2d__wadd(B.w, ga2d__wmul(g->iib, g->x->rimp));
    }
    ga2d__wstore(c->sbodies, g->a, g->move_a, &A);
    ga2d__wstore(c->sbodies, g->b, g->move_b, &B);
}

/* Stage, over the groups: each point's accumulated impulses applied again
   at its anchors now. */
static void ga2d__warm_start(ga2d__step_context *c, int begin, int end)
{
    int gi, find = c->masses_stale, friction = c->world->def.enable_friction;
    for (gi = begin; gi < end; ++gi) {
        ga2d__group *g = &c->groups[gi];
        if (g->extras) ga2d__warm_group(c, g, 1, find, friction);
        else if (find) ga2d__warm_group(c, g, 0, 1, friction);
        else ga2d__warm_group(c, g, 0, 0, friction);
    }
}

enum { GA2D__BIAS_NONE, GA2D__BIAS_SOFT, GA2D__BIAS_BAUMGARTE };

/* One pass of sequential impulses over every group: for each point, the
   normal impulse that makes the approach speed (plus the bias) zero,
   accumulated and kept >= 0; then Coulomb friction, the tangent impulse
   accumulated within +-mu times the point's normal impulse.  A point still
   apart (separation s > 0) may approach by s in this substep: that is the
   speculative contact that catches fast bodies.
   The soft step's soft pass solves no friction and no rolling resistance
   against velocity: they act in the warm start and the relax pass.  The
   soft pass's velocities carry the push-out (the bias), which the relax
   pass takes away again along the normals; friction solved on them turned
   that fictitious motion into tangent impulse that stayed (a light body
   squeezed under a heavy one tilts, its deeper corner is pushed harder,
   and the friction of that push drove the load sideways, the error
   growing step after step: a 400:1 plank rocked its boxes and crept 7 cm
   in 10 s).  The soft pass only keeps the warm-started tangent impulse
   within mu times the normal impulse it has just found, so that a point
   letting go lets go of its friction before the positions move (else the
   warm start's friction would act over the substep and the relax pass
   take it back at anchors moved since: energy from nothing). */
/* What a pass's groups share: the bias kind, switches and splatted
   constants. */
typedef struct ga2d__pass {
    int bias_kind, friction;
    int fresh;                  /* the bodies moved since the masses were found: find them again */
    ga2d__w zero, one, winv_h, low, slop, nslop, baumgarte;
    ga2d__w soft_rate, soft_mass, soft_impulse;    /* between moving bodies */
    ga2d__w stiff_rate, stiff_mass, stiff_impulse; /* against one the solver does not move */
} ga2d__pass;

/* One group's pass, in phases over what it carries from one to the
   next: the lanes' bodies, and each point's scaled inverse mass and own
   update (ga2d__wblock).  A group's pass is one long chain of dependent
   arithmetic (each friction point sees the last one's change), longer
   than the processor looks ahead, so two groups of a colour, which move
   no body in common, run phase by phase side by side
   (ga2d__solve_pair): each one's chain fills the other's waits.
   `extras` (a constant where it is inlined) leaves a polygon world's
   groups without the round, conveyor and rolling code, and `fresh`
   (ps->fresh, a constant too) finds the anchors and masses first
   (ga2d__wfind). */
typedef struct ga2d__gpass {
    ga2d__wbody A, B;
    ga2d__w inv_a[2], own[2];
} ga2d__gpass;

/* The bodies loaded (and the anchors and masses found, `fresh`), and
   each point's update alone. */
static GA2D__HOT void ga2d__pass_begin(ga2d__step_context *c, ga2d__group *g, const ga2d__pass *ps, ga2d__gpass *st,
                                       int extras, int fresh)
{
    const ga2d__w zero = ps->zero, one = ps->one;
    const int bias_kind = ps->bias_kind;
    const ga2d__warms *r = g->arm;
    ga2d__w *inv_a = st->inv_a, *own = st->own;
    ga2d__w soft_rate = zero, soft_mass = one, soft_impulse = zero, vn, dvx, dvy, lin;
    int k;
    ga2d__wload(c->sbodies, g->a, &st->A, fresh);
    ga2d__wload(c->sbodies, g->b, &st->B, fresh);
    if (fresh) ga2d__wfind(g, &st->A, &st->B, ps->friction, extras);
    if (bias_kind == GA2D__BIAS_SOFT) { /* the lanes that move both bodies are soft, the others stiff */
        ga2d__wmask both = ga2d__wand(g->move_a, g->move_b);
        soft_rate = ga2d__wsel(both, ps->soft_rate, ps->stiff_rate);
        soft_mass = ga2d__wsel(both, ps->soft_mass, ps->stiff_mass);
        soft_impulse = ga2d__wsel(both, ps->soft_impulse, ps->stiff_impulse);
    }
    /* the centres' relative velocity along n, shared by both points */
    dvx = ga2d__wsub(st->B.vx, st->A.vx);
    dvy = ga2d__wsub(st->B.vy, st->A.vy);
    lin = ga2d__wdot(dvx, dvy, g->nx, g->ny);
    for (k = 0; k < 2; ++k) {
        ga2d__w s = g->sep[k];
        ga2d__wmask apart = ga2d__wgt(s, zero);
        ga2d__w bias = zero, mass_scale = one, impulse_scale = zero;
        /* the masses are at the anchors the impulses act at now (they
           follow the bodies: ga2d__point_now).  A mass m at a point whose
           true inverse mass is K changes its approach speed by a factor 1
           - m K a pass: the passes diverge, and push energy in, once m K >
           2.  Masses kept from the step's start reached m K = 470 where
           the shared point of a wide speculative gap between fast bodies
           had moved a metre sideways (0.8 m of lever arm on a 0.1 m
           disc), and the step went to NaN in two substeps; NGS's moves
           did the same with deep overlaps of small bodies.  Found once
           per position of the bodies (ga2d__wfind) */
        vn = ga2d__wrelative(&st->A, &st->B, lin, r[k].na, r[k].nb);
        if (bias_kind == GA2D__BIAS_SOFT) {
            /* the spring in impulse: its bias's push, and the part of
               the impulse it carries that the soft step lets go each pass
               (impulse_scale nimp).  Their sum is what the pass adds
               beyond holding the point's load: at rest under a load the
               two cancel (the spring sits at its deflection), and -sum /
               m_eff is the speed the pass drives the point apart at.  That
               speed is capped at the push-out speed: sum >= m_eff
               (-v_push).  The cap limits how fast a point pushes out,
               never the load it holds (the spring stays linear: a load
               sinks as M g / k at any mass ratio).  Capping the bias alone
               capped the load a point carries at m_eff a2 v_push / h (a2 =
               h w (2 zeta + h w), ga2d__make_soft), and a heavier load sank
               through at a steady speed (a circle of density 1000 passed
               through one of density 1); keeping the sum at or above
               min(capped push + let go, 0) held any load but left a dead
               band past the spring's deflection in which nothing pushed
               back: a 1000:1 plank on two boxes bobbed 2.4 cm for ever.
               Pushes add up along a column of overlapped boxes, each
               contact's within the cap. */
            ga2d__w spring, floor;
            mass_scale = ga2d__wsel(apart, one, soft_mass);
            impulse_scale = ga2d__wsel(apart, zero, soft_impulse);
            inv_a[k] = ga2d__wmul(g->nmass[k], mass_scale);
            spring = ga2d__wadd(ga2d__wmul(inv_a[k], ga2d__wmul(soft_rate, s)), ga2d__wmul(impulse_scale, g->nimp[k]));
            floor = ga2d__wmul(inv_a[k], ps->low);
            spring = ga2d__wsel(ga2d__wgt(floor, spring), floor, spring);
            spring = ga2d__wsel(apart, ga2d__wmul(inv_a[k], ga2d__wmul(s, ps->winv_h)), spring);
            own[k] = ga2d__wsub(zero, ga2d__wadd(ga2d__wmul(inv_a[k], vn), spring));
            continue;
        }
        if (bias_kind == GA2D__BIAS_BAUMGARTE) {
            bias = ga2d__wmul(ps->baumgarte, ga2d__wadd(s, ps->slop));
            bias = ga2d__wsel(ga2d__wgt(ps->low, bias), ps->low, bias);
            bias = ga2d__wsel(ga2d__wgt(ps->nslop, s), bias, zero);
        }
        bias = ga2d__wsel(apart, ga2d__wmul(s, ps->winv_h), bias);
        /* the point's own update (its impulse alone, unclamped) and
           its share of the coupling, both in the point's own scale */
        inv_a[k] = ga2d__wmul(g->nmass[k], mass_scale);
        own[k] = ga2d__wsub(zero, ga2d__wadd(ga2d__wmul(inv_a[k], ga2d__wadd(vn, bias)), ga2d__wmul(impulse_scale, g->nimp[k])));
    }
}

/* The points' normal impulses, both at once (they were found together). */
static GA2D__HOT void ga2d__pass_normal(ga2d__group *g, ga2d__gpass *st)
{
    const ga2d__warms *r = g->arm;
    ga2d__w lambda[2], ma, mb, tsum;
    ga2d__wblock(g, st->inv_a, st->own, lambda);
    g->nimp[0] = ga2d__wadd(g->nimp[0], lambda[0]);
    g->nimp[1] = ga2d__wadd(g->nimp[1], lambda[1]);
    tsum = ga2d__wadd(lambda[0], lambda[1]);
    ma = ga2d__wadd(ga2d__wmul(r[0].na, lambda[0]), ga2d__wmul(r[1].na, lambda[1]));
    mb = ga2d__wadd(ga2d__wmul(r[0].nb, lambda[0]), ga2d__wmul(r[1].nb, lambda[1]));
    ga2d__wapply(g, &st->A, &st->B, ga2d__wmul(g->nx, tsum), ga2d__wmul(g->ny, tsum), ma, mb);
}

/* Friction at point k; the soft pass's cone takes both points at k = 0. */
static GA2D__HOT void ga2d__pass_friction(ga2d__group *g, const ga2d__pass *ps, ga2d__gpass *st, int k, int extras)
{
    const ga2d__w zero = ps->zero;
    const ga2d__warms *r = g->arm;
    ga2d__w tx = g->ny, ty = ga2d__wsub(zero, g->nx), ma, mb, tsum;
    if (!ps->friction) return;
    if (ps->bias_kind == GA2D__BIAS_SOFT) {
        ga2d__w d[2];
        if (k > 0) return;
        /* the cone only: the pass's velocities carry the bias.  No
           velocity is read, so both points' changes go at once */
        for (k = 0; k < 2; ++k) {
            ga2d__w cap = ga2d__wmul(g->friction, g->nimp[k]);
            ga2d__w total = ga2d__wclamp(g->timp[k], ga2d__wsub(zero, cap), cap);
            d[k] = ga2d__wsub(total, g->timp[k]);
            g->timp[k] = total;
        }
        tsum = ga2d__wadd(d[0], d[1]);
        ma = ga2d__wadd(ga2d__wmul(r[0].ta, d[0]), ga2d__wmul(r[1].ta, d[1]));
        mb = ga2d__wadd(ga2d__wmul(r[0].tb, d[0]), ga2d__wmul(r[1].tb, d[1]));
        ga2d__wapply(g, &st->A, &st->B, ga2d__wmul(tx, tsum), ga2d__wmul(ty, tsum), ma, mb);
    } else {
        /* point by point: the second sees the first's change */
        ga2d__wbody *A = &st->A, *B = &st->B;
        ga2d__w cap = ga2d__wmul(g->friction, g->nimp[k]), dt, total, vt;
        vt = ga2d__wrelative(A, B, ga2d__wdot(ga2d__wsub(B->vx, A->vx), ga2d__wsub(B->vy, A->vy), tx, ty), r[k].ta, r[k].tb);
        if (extras && g->conveyor) vt = ga2d__wsub(vt, g->x->tspeed);
        dt = ga2d__wsub(zero, ga2d__wmul(g->tmass[k], vt));
        total = ga2d__wclamp(ga2d__wadd(g->timp[k], dt), ga2d__wsub(zero, cap), cap);
        dt = ga2d__wsub(total, g->timp[k]);
        g->timp[k] = total;
        ga2d__wapply(g, A, B, ga2d__wmul(tx, dt), ga2d__wmul(ty, dt), ga2d__wmul(r[k].ta, dt), ga2d__wmul(r[k].tb, dt));
    }
}

/* Rolling resistance (`extras`), and the velocities back. */
static GA2D__HOT void ga2d__pass_end(ga2d__step_context *c, ga2d__group *g, const ga2d__pass *ps, ga2d__gpass *st, int extras)
{
    if (extras && g->rolling) {
        /* rolling resistance: a torque impulse against the bodies'
           relative spin, accumulated within +-c r times the normal
           impulse (the points' sum); the soft pass only keeps it within
           the cone, as friction */
        ga2d__w cap = ga2d__wmul(g->x->rr, ga2d__wadd(g->nimp[0], g->nimp[1]));
        const ga2d__w zero = ps->zero;
        ga2d__w dl = ps->bias_kind == GA2D__BIAS_SOFT ? zero : ga2d__wsub(zero, ga2d__wmul(g->x->rmass, ga2d__wsub(st->B.w, st->A.w)));
        ga2d__w total = ga2d__wclamp(ga2d__wadd(g->x->rimp, dl), ga2d__wsub(zero, cap), cap);
        dl = ga2d__wsub(total, g->x->rimp);
        g->x->rimp = total;
        st->A.w = ga2d__wsub(st->A.w, ga2d__wmul(g->iia, dl));
        st->B.w = ga2d__wadd(st->B.w, ga2d__wmul(g->iib, dl));
    }
    ga2d__wstore(c->sbodies, g->a, g->move_a, &st->A);
    ga2d__wstore(c->sbodies, g->b, g->move_b, &st->B);
}

static GA2D__HOT void ga2d__solve_group(ga2d__step_context *c, ga2d__group *g, const ga2d__pass *ps, int extras, int fresh)
{
    ga2d__gpass st;
    ga2d__pass_begin(c, g, ps, &st, extras, fresh);
    ga2d__pass_normal(g, &st);
    ga2d__pass_friction(g, ps, &st, 0, extras);
    ga2d__pass_friction(g, ps, &st, 1, extras);
    ga2d__pass_end(c, g, ps, &st, extras);
}

/* Two groups of one colour (no moved body in common, so either order
   gives the same bits), phase by phase side by side (`extras` if either
   has them: the other's flags are clear). */
static GA2D__HOT void ga2d__solve_pair(ga2d__step_context *c, ga2d__group *g, const ga2d__pass *ps, int extras, int fresh)
{
    ga2d__gpass st[2];
    ga2d__pass_begin(c, &g[0], ps, &st[0], extras, fresh);
    ga2d__pass_begin(c, &g[1], ps, &st[1], extras, fresh);
    ga2d__pass_normal(&g[0], &st[0]);
    ga2d__pass_normal(&g[1], &st[1]);
    ga2d__pass_friction(&g[0], ps, &st[0], 0, extras);
    ga2d__pass_friction(&g[1], ps, &st[1], 0, extras);
    ga2d__pass_friction(&g[0], ps, &st[0], 1, extras);
    ga2d__pass_friction(&g[1], ps, &st[1], 1, extras);
    ga2d__pass_end(c, &g[0], ps, &st[0], extras);
    ga2d__pass_end(c, &g[1], ps, &st[1], extras);
}

static GA2D__HOT void ga2d__solve_contacts(ga2d__step_context *c, int begin, int end, int bias_kind)
{
    ga2d_world *w = c->world;
    ga2d_real inv_h = c->inv_h, push = w->def.contact_push_max_velocity * w->def.length_units_per_meter;
    ga2d__pass ps;
    int gi, stop;
    ps.bias_kind = bias_kind;
    ps.friction = w->def.enable_friction;
    ps.fresh = c->masses_stale;
    ps.zero = ga2d__wsplat(0);
    ps.one = ga2d__wsplat(1);
    ps.winv_h = ga2d__wsplat(inv_h);
    ps.low = ga2d__wsplat(-push);
    ps.slop = ga2d__wsplat(w->slop);
    ps.nslop = ga2d__wsplat(-w->slop);
    ps.baumgarte = ga2d__wsplat(GA2D__BAUMGARTE * inv_h);
    ps.soft_rate = ga2d__wsplat(c->soft.bias_rate);
    ps.soft_mass = ga2d__wsplat(c->soft.mass_scale);
    ps.soft_impulse = ga2d__wsplat(c->soft.impulse_scale);
    ps.stiff_rate = ga2d__wsplat(c->stiff.bias_rate);
    ps.stiff_mass = ga2d__wsplat(c->stiff.mass_scale);
    ps.stiff_impulse = ga2d__wsplat(c->stiff.impulse_scale);
    for (gi = begin, stop = begin; gi < end;) {
        ga2d__group *g = &c->groups[gi];
        int pair;
        if (gi >= stop) stop = ga2d__colour_end(c, gi, end);
        pair = gi + 1 < stop;
        if (pair && (g[0].extras || g[1].extras)) ga2d__solve_pair(c, g, &ps, 1, ps.fresh);
        else if (pair && ps.fresh) ga2d__solve_pair(c, g, &ps, 0, 1);
        else if (pair) ga2d__solve_pair(c, g, &ps, 0, 0);
        else if (g->extras) ga2d__solve_group(c, g, &ps, 1, ps.fresh);
        else if (ps.fresh) ga2d__solve_group(c, g, &ps, 0, 1);
        else ga2d__solve_group(c, g, &ps, 0, 0);
        gi += 1 + pair;
    }
}

/* Stages, over the groups: the soft pass, the relax pass (rigid, no bias)
   and the Baumgarte pass. */
static void ga2d__solve_soft(ga2d__step_context *c, int begin, int end) { ga2d__solve_contacts(c, begin, end, GA2D__BIAS_SOFT); }
static void ga2d__solve_rigid(ga2d__step_context *c, int begin, int end) { ga2d__solve_contacts(c, begin, end, GA2D__BIAS_NONE); }
static void ga2d__solve_baumgarte(ga2d__step_context *c, int begin, int end)
{
    ga2d__solve_contacts(c, begin, end, GA2D__BIAS_BAUMGARTE);
}

/* Lane l's fields for round shapes, conveyors, rolling resistance and
   hit events.
   The first lane of a group that needs them zeroes them in every other
   lane (their group is flagged from then on, so every later lane writes
   its own); a group without them never writes them. */
static void ga2d__lane_extras(ga2d__group *g, int l, const ga2d__contact_constraint *c, const ga2d__contact_constraint *none)
{
    int k, j;
    if (!g->extras) {
        for (j = 0; j < GA2D__LANES; ++j) {
            if (j == l) continue;
            for (k = 0; k < 2; ++k)
                GA2D__LANE(g->x->oax[k], j) = GA2D__LANE(g->x->oay[k], j) = GA2D__LANE(g->x->obx[k], j) = GA2D__LANE(g->x->oby[k], j) = 0;
            GA2D__LANE(g->x->tspeed, j) = GA2D__LANE(g->x->rr, j) = GA2D__LANE(g->x->rmass, j) = GA2D__LANE(g->x->rimp, j) = 0;
            GA2D__LANE(g->x->tw, j) = 0;
            GA2D__LANE(g->x->npeak[0], j) = GA2D__LANE(g->x->npeak[1], j) = 0;
        }
        g->extras = 1;
    }
    if (c->round_a != 0 || c->round_b != 0) g->round = 1;
    if (c->tangent_speed != 0) g->conveyor = 1;
    if (c->rolling != 0) g->rolling = 1;
    if (c->hits) g->hits = 1;
    GA2D__LANE(g->x->npeak[0], l) = GA2D__LANE(g->x->npeak[1], l) = 0;
    GA2D__LANE(g->x->tspeed, l) = c->tangent_speed;
    GA2D__LANE(g->x->rr, l) = c->rolling;
    GA2D__LANE(g->x->rmass, l) = c->rolling != 0 && c->inv_ia + c->inv_ib > 0 ? 1 / (c->inv_ia + c->inv_ib) : 0;
    GA2D__LANE(g->x->rimp, l) = 0;
    GA2D__LANE(g->x->tw, l) = (c->round_a != 0) == (c->round_b != 0) ? 0 : (c->round_b != 0 ? GA2D__R(0.5) : GA2D__R(-0.5));
    for (k = 0; k < 2; ++k) {
        /* round shapes: core anchors that turn, and what lies along n that does not */
        const ga2d__cpoint *p = k < c->count ? &c->p[k] : &none->p[0];
        ga2d_vec oa = ga2d__round_offset(c, p, 0), ob = ga2d__round_offset(c, p, 1);
        ga2d_vec ca = c->round_a != 0 ? ga2d_vec_sub(p->ra, oa) : p->ra, cb = c->round_b != 0 ? ga2d_vec_sub(p->rb, ob) : p->rb;
        GA2D__LANE(g->x->oax[k], l) = oa.x;
        GA2D__LANE(g->x->oay[k], l) = oa.y;
        GA2D__LANE(g->x->obx[k], l) = ob.x;
        GA2D__LANE(g->x->oby[k], l) = ob.y;
        GA2D__LANE(g->rax[k], l) = ca.x;
        GA2D__LANE(g->ray[k], l) = ca.y;
        GA2D__LANE(g->rbx[k], l) = cb.x;
        GA2D__LANE(g->rby[k], l) = cb.y;
    }
}

/* Lane l of group g holds constraint c (d: B's centre less A's), every
   field a polygon world reads written: a point c lacks takes `none`'s (all
   zero), and so does an empty lane (c = none), so the masses ga2d__wfind
   finds there are zero (it finds every mass before a pass reads one).
   The anchors are the points' own; a round side's are made core anchors
   by ga2d__lane_extras. */
static void ga2d__lane_write(ga2d__group *g, int l, const ga2d__contact_constraint *c, ga2d_vec d,
                             const ga2d__contact_constraint *none)
{
    int k;
    GA2D__LANE(g->nx, l) = c->normal.x;
    GA2D__LANE(g->ny, l) = c->normal.y;
    GA2D__LANE(g->friction, l) = c->friction;
    GA2D__LANE(g->ima, l) = c->inv_ma;
    GA2D__LANE(g->iia, l) = c->inv_ia;
    GA2D__LANE(g->imb, l) = c->inv_mb;
    GA2D__LANE(g->iib, l) = c->inv_ib;
    GA2D__LANE(g->dx, l) = d.x;
    GA2D__LANE(g->dy, l) = d.y;
    GA2D__LANE(g->share, l) = ga2d__share(c);
    GA2D__LANE(g->has2, l) = c->count == 2 ? 1 : 0;
    for (k = 0; k < 2; ++k) {
        const ga2d__cpoint *p = k < c->count ? &c->p[k] : &none->p[0];
        GA2D__LANE(g->rax[k], l) = p->ra.x;
        GA2D__LANE(g->ray[k], l) = p->ra.y;
        GA2D__LANE(g->rbx[k], l) = p->rb.x;
        GA2D__LANE(g->rby[k], l) = p->rb.y;
        GA2D__LANE(g->adjust[k], l) =
            p->separation - ((d.x + (p->rb.x - p->ra.x)) * c->normal.x + (d.y + (p->rb.y - p->ra.y)) * c->normal.y);
        GA2D__LANE(g->nimp[k], l) = p->normal_impulse;
        GA2D__LANE(g->timp[k], l) = p->tangent_impulse;
    }
}

/* Puts constraint ci into the next free lane of group gi: only the
   lane's constraint and the group's count (beside it, in `fill`) are
   written here, on the calling thread; ga2d__fill_groups writes the
   groups themselves (a kilobyte each) on the workers. */
static void ga2d__lane_put(ga2d__step_context *c, int gi, int ci)
{
    int lane = gi * GA2D__LANES + c->fill[gi].count++;
    c->lane_constraints[lane] = ci;
    c->constraints[ci].lane = lane;
}

/* The first group from gi on with a free lane (or group_count): a full
   group points past itself (skip), and the path is halved as it is
   walked.  It reads the groups' fill beside them, not the groups (a
   kilobyte each: a probe of theirs was a cache miss). */
static int ga2d__group_free(ga2d__step_context *c, int gi)
{
    ga2d__fill *f = c->fill;
    while (gi < c->group_count && f[gi].count == GA2D__LANES) {
        int next = f[gi].skip;
        if (next < c->group_count && f[next].count == GA2D__LANES) f[gi].skip = f[next].skip;
        gi = next;
    }
    return gi;
}

/* The solver bodies, one per body slot and a dummy past the end (an
   empty lane's): 0 when memory runs out (the step reports it). */
static int ga2d__reserve_sbodies(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    ga2d__sbody *dummy;
    if (!ga2d__reserve_slots(w, w->body_used)) {
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return 0;
    }
    dummy = &c->sbodies[w->body_used];
    memset(dummy, 0, sizeof *dummy);
    dummy->dqc = 1;
    return 1;
}

/* A body the solver does not move (static or asleep) is not gathered per
   pass: it is seen as it is, at rest where the step began.  (Lanes that
   share such a body write it the same values.) */
static void ga2d__still_body(ga2d__step_context *c, int slot)
{
    const ga2d__body *b = &c->world->bodies[slot];
    ga2d__sbody *s = &c->sbodies[slot];
    if (b->move_index >= 0) return;
    s->vx = b->sim.v.x;
    s->vy = b->sim.v.y;
    s->w = b->sim.w;
    s->pad = s->dpx = s->dpy = s->dqs = 0;
    s->dqc = 1;
}

/* The lowest and the highest colour in `set` (a nonzero mask): the
   compiler's bit scan where it has one (a loop over the bits was 2 % of a
   large pyramid's step). */
static int ga2d__lowest_bit(uint32_t set)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctz(set);
#else
    int k = 0;
    while (!(set >> k & 1u)) ++k;
    return k;
#endif
}
static int ga2d__highest_bit(uint32_t set)
{
#if defined(__GNUC__) || defined(__clang__)
    return 31 - __builtin_clz(set);
#else
    int k = GA2D__COLOURS - 1;
    while (!(set >> k & 1u)) --k;
    return k;
#endif
}

/* A constraint's colour, given the colours its moved bodies have taken
   (not all of them): the lowest past all of theirs, so that each body's
   constraints come in their canonical order as they would one at a time
   (bottom up in a pile: the order stacks converge in); when none is past
   them, the highest free one, as late in the pass as it can be.  Taking
   the lowest free one instead made large_pyramid's top box drift 0.375 m
   where the canonical order gives 0.352 m; this gives 0.359 m. */
static int ga2d__pick_colour(uint32_t taken)
{
    uint32_t below = taken;
    below |= below >> 1;
    below |= below >> 2;
    below |= below >> 4;
    below |= below >> 8;
    below |= below >> 16;
    return ~below ? ga2d__lowest_bit(~below) : ga2d__highest_bit(~taken);
}

/* Out of memory while colouring: the step reports it, and solves no
   contact and no joint.  0. */
static int ga2d__solve_nothing(ga2d__step_context *c)
{
    c->group_count = c->colour_count = c->joint_active = 0;
    c->lane_key_count = -1;
    c->error = GA2D_ERR_OUT_OF_MEMORY;
    return 0;
}

/* Room for one more group, opened (0 when memory runs out). */
static int ga2d__open_group(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    if (!ga2d__grow(&w->mem, (void **)&c->groups, &c->group_capacity, c->group_count + 1, sizeof *c->groups) ||
        !ga2d__grow(&w->mem, (void **)&c->fill, &c->fill_capacity, c->group_count + 1, sizeof *c->fill) ||
        !ga2d__grow(&w->mem, (void **)&c->lane_constraints, &c->lane_constraint_capacity,
                    (c->group_count + 1) * GA2D__LANES, sizeof *c->lane_constraints))
        return ga2d__solve_nothing(c);
    c->fill[c->group_count].count = c->fill[c->group_count].skip = 0;
    ++c->group_count;
    return 1;
}

/* Whether constraint cc moves its A, its B (some inverse mass or inertia
   of that side is not zero: ga2d__prepare_constraints). */
static int ga2d__moves_a(const ga2d__contact_constraint *cc) { return cc->moves & 1; }
static int ga2d__moves_b(const ga2d__contact_constraint *cc) { return cc->moves >> 1; }

/* A colour for a constraint that moves bodies a (if ma) and b (if mb),
   taken in their masks; GA2D__OVERFLOW when they have all the colours
   between them. */
#define GA2D__OVERFLOW GA2D__COLOURS
static int ga2d__take_colour(uint32_t *mask, int a, int ma, int b, int mb)
{
    uint32_t taken = (ma ? mask[a] : 0) | (mb ? mask[b] : 0);
    int k;
    if (taken == ~(uint32_t)0) return GA2D__OVERFLOW;
    k = ga2d__pick_colour(taken);
    if (ma) mask[a] |= (uint32_t)1 << k;
    if (mb) mask[b] |= (uint32_t)1 << k;
    return k;
}

/* The joints' colours, first, in creation order, so that a body's joints
   come before its contacts in a pass as they did when all the joints
   went first (their colours are found as the contacts' are,
   ga2d__pick_colour); a side the joint does not move gets its solver
   body here.  Counts each colour's joints in `count`, and its bare hinges
   (ga2d__bare_hinge) in `bare`; a joint's colour is kept with GA2D__BARE
   set if it is one. */
#define GA2D__BARE 0x100
static int ga2d__bare_hinge(const ga2d__joint *j)
{
    return j->type == GA2D_JOINT_REVOLUTE && !j->enable_spring && !j->enable_motor && !j->enable_limit;
}

static void ga2d__colour_joints(ga2d__step_context *c, int *count, int *bare)
{
    ga2d_world *w = c->world;
    int i;
    for (i = 0; i < c->joint_active; ++i) {
        const ga2d__joint *j = &w->joints[c->joint_order[i]];
        int ma = j->ima != 0 || j->iia != 0, mb = j->imb != 0 || j->iib != 0;
        int k = ga2d__take_colour(c->colour_masks, j->body[0], ma, j->body[1], mb);
        c->joint_colours[i] = k | (ga2d__bare_hinge(j) ? GA2D__BARE : 0);
        if (!ma) ga2d__still_body(c, j->body[0]);
        if (!mb) ga2d__still_body(c, j->body[1]);
        if (k == GA2D__OVERFLOW) continue;
        ++count[k];
        bare[k] += ga2d__bare_hinge(j);
        if (k + 1 > c->colour_count) c->colour_count = k + 1;
    }
}

/* The joints in colour order, each colour's bare hinges first (`bare`
   of them: ga2d__pack_hinges packs them) and then the rest, each part in
   creation order; the overflow's last, where the colours' counts `count`
   say.  Where each came from is kept (joint_perm), for a step that keeps
   the colouring. */
static void ga2d__sort_joints(ga2d__step_context *c, const int *count, const int *bare)
{
    int next[GA2D__COLOURS + 1], rest[GA2D__COLOURS + 1], k, i;
    c->joint_start[0] = 0;
    for (k = 0; k < c->colour_count; ++k) c->joint_start[k + 1] = c->joint_start[k] + count[k];
    for (k = 0; k <= c->colour_count; ++k) {
        c->joint_bare[k] = k < c->colour_count ? bare[k] : 0;
        next[k] = c->joint_start[k];
        rest[k] = next[k] + c->joint_bare[k];
    }
    for (i = 0; i < c->joint_active; ++i) {
        int colour = c->joint_colours[i] & ~GA2D__BARE;
        k = colour == GA2D__OVERFLOW ? c->colour_count : colour;
        int at = c->joint_colours[i] & GA2D__BARE && k < c->colour_count ? next[k]++ : rest[k]++;
        c->joint_sorted[at] = c->joint_order[i];
        c->joint_perm[at] = i;
    }
    ga2d__swap_arrays((void **)&c->joint_order, &c->joint_order_capacity, (void **)&c->joint_sorted, &c->joint_sorted_capacity);
}

/* What the step keeps of each constraint it has given a lane: whether
   it needs the groups' extras, whether it is round (counted), and a side
   the solver does not move gets its solver body here, once per lane that
   has it (a moving one's is gathered before each run of passes). */
static GA2D__HOT void ga2d__lane_seen(ga2d__step_context *c, const ga2d__contact_constraint *cc, int *extras, int *round)
{
    *extras |= cc->needs_extras;
    *round += cc->round_a != 0 || cc->round_b != 0;
    if (!ga2d__moves_a(cc)) ga2d__still_body(c, cc->a);
    if (!ga2d__moves_b(cc)) ga2d__still_body(c, cc->b);
}

/* The lanes' end: the round count, and the groups' extras when some
   constraint needs them; 0 when memory for those runs out (the step
   reports it and solves nothing). */
static int ga2d__lanes_done(ga2d__step_context *c, int extras, int round)
{
    ga2d_world *w = c->world;
    w->counters.round_contacts += round;
    c->group_extras_on = extras;
    if (extras && !ga2d__grow(&w->mem, (void **)&c->group_extras, &c->group_extra_capacity, c->group_count,
                              sizeof *c->group_extras))
        return ga2d__solve_nothing(c);
    return 1;
}

/* A constraint or a joint as the colouring reads it: its bodies, which
   of them it moves (1: A, 2: B) and, for a joint, whether it is a bare
   hinge (4).  The colouring is a function of these alone, in order: the
   joints' in creation order, then the constraints' in theirs. */
struct ga2d__lane_key { int a, b, moves, lane; }; /* lane: a constraint's in the kept colouring */

static void ga2d__joint_key(const ga2d__joint *j, ga2d__lane_key *k)
{
    k->a = j->body[0];
    k->b = j->body[1];
    k->moves = (j->ima != 0 || j->iia != 0) | (j->imb != 0 || j->iib != 0) << 1 | ga2d__bare_hinge(j) << 2;
    k->lane = -1;
}

/* A body the kept colouring's constraints do not move, listed for its
   solver body to be written each step the colouring is kept (a pile's
   ground comes in runs: the last one listed is not listed again).  0: out
   of memory, reported. */
static int ga2d__keep_still(ga2d__step_context *c, int slot)
{
    ga2d_world *w = c->world;
    if (c->still_count > 0 && c->still_slots[c->still_count - 1] == slot) return 1;
    if (!ga2d__grow(&w->mem, (void **)&c->still_slots, &c->still_capacity, c->still_count + 1, sizeof *c->still_slots)) {
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return 0;
    }
    c->still_slots[c->still_count++] = slot;
    return 1;
}

/* Remembers the colouring just made, with the constraints it read, for
   the next step to keep if it reads the same (ga2d__lanes_kept).  Out of
   memory, it is not remembered and the step reports it (every failed
   allocation is reported), but solves as it would. */
static void ga2d__keep_lanes(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int i, n = c->constraint_count;
    if (!ga2d__grow(&w->mem, (void **)&c->lane_keys, &c->lane_key_capacity, n + c->joint_active, sizeof *c->lane_keys)) {
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return;
    }
    c->still_count = 0;
    for (i = 0; i < n; ++i) {
        const ga2d__contact_constraint *cc = &c->constraints[i];
        c->lane_keys[i].a = cc->a;
        c->lane_keys[i].b = cc->b;
        c->lane_keys[i].moves = cc->moves;
        c->lane_keys[i].lane = cc->lane;
        if (!ga2d__moves_a(cc) && !ga2d__keep_still(c, cc->a)) return;
        if (!ga2d__moves_b(cc) && !ga2d__keep_still(c, cc->b)) return;
    }
    /* the joints in creation order: where ga2d__sort_joints left it */
    for (i = 0; i < c->joint_active; ++i) ga2d__joint_key(&w->joints[c->joint_sorted[i]], &c->lane_keys[n + i]);
    c->lane_key_count = n + c->joint_active;
    c->kept_joints = c->joint_active;
    c->kept_groups = c->group_count;
    c->kept_colours = c->colour_count;
}

/* The kept colouring's joint order: each colour's joints where the
   colouring put them (joint_perm, positions in creation order), and a
   side a joint does not move gets its solver body. */
static void ga2d__joints_kept(ga2d__step_context *c)
{
    int p;
    for (p = 0; p < c->joint_active; ++p) c->joint_sorted[p] = c->joint_order[c->joint_perm[p]];
    ga2d__swap_arrays((void **)&c->joint_order, &c->joint_order_capacity, (void **)&c->joint_sorted, &c->joint_sorted_capacity);
    /* from the keys in listing order (ga2d__joint_key), not the joints'
       records in the colours' order: a cache miss each */
    for (p = 0; p < c->joint_active; ++p) {
        const ga2d__lane_key *k = &c->joint_keys[p];
        if (!(k->moves & 1)) ga2d__still_body(c, k->a);
        if (!(k->moves & 2)) ga2d__still_body(c, k->b);
    }
}

/* Stage, over the constraints, while a colouring is kept: whether each
   reads as the kept colouring read it, and if so its lane there; each
   range's verdict in its first block's tally: the round count (times
   GA2D__KEPT_ROUND), whether some constraint needs extras, and whether
   some differs. */
#define GA2D__KEPT_EXTRAS 1
#define GA2D__KEPT_DIFFERS 2
#define GA2D__KEPT_ROUND 4
static void ga2d__check_kept(ga2d__step_context *c, int begin, int end)
{
    int i, verdict = 0;
    for (i = begin; i < end; ++i) {
        ga2d__contact_constraint *cc = &c->constraints[i];
        const ga2d__lane_key *k = &c->lane_keys[i];
        if (k->a != cc->a || k->b != cc->b || k->moves != cc->moves) {
            verdict |= GA2D__KEPT_DIFFERS;
            break;
        }
        cc->lane = k->lane;
        verdict |= cc->needs_extras ? GA2D__KEPT_EXTRAS : 0;
        verdict += cc->round_a != 0 || cc->round_b != 0 ? GA2D__KEPT_ROUND : 0;
    }
    c->tally[begin / GA2D__SPLIT_BLOCK] = verdict; /* a range's own slot (ranges start on blocks) */
}

/* The last step's colouring, kept when this step's joints and
   constraints are the same bodies, moved the same way, in the same order
   (and the same joints bare hinges or not): the colouring would come out
   the same, so the groups' fills, lanes, the colour starts and the
   joints' places in them are still right, and only what the step keeps
   per constraint and joint is written again (each joint's place in the
   order, each constraint's lane, on the workers: ga2d__check_kept; the
   still bodies' solver bodies, the extras and the round count).  A
   resting pile or a hanging net keeps its colouring step after step; 0
   when not kept. */
static int ga2d__lanes_kept(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int i, extras = 0, round = 0, n = c->constraint_count, blocks = (n + GA2D__SPLIT_BLOCK - 1) / GA2D__SPLIT_BLOCK;
    if (c->joint_active != c->kept_joints || c->lane_key_count != n + c->joint_active) return 0;
    if (!ga2d__reserve_sbodies(c) || /* as the colouring anew would report it */
        !ga2d__grow(&w->mem, (void **)&c->tally, &c->tally_capacity, blocks, sizeof *c->tally)) {
        (void)ga2d__solve_nothing(c);
        return 1;
    }
    for (i = 0; i < c->joint_active; ++i) {
        const ga2d__lane_key *k = &c->lane_keys[n + i], *now = &c->joint_keys[i];
        if (k->a != now->a || k->b != now->b || k->moves != now->moves) return 0;
    }
    if (blocks > 0) memset(c->tally, 0, (size_t)blocks * sizeof *c->tally);
    ga2d__run_split(c, ga2d__check_kept, n);
    for (i = 0; i < blocks; ++i) {
        if (c->tally[i] & GA2D__KEPT_DIFFERS) return 0;
        extras |= c->tally[i] & GA2D__KEPT_EXTRAS;
        round += c->tally[i] / GA2D__KEPT_ROUND;
    }
    ga2d__joints_kept(c);
    for (i = 0; i < c->still_count; ++i) ga2d__still_body(c, c->still_slots[i]);
    c->group_count = c->kept_groups;
    c->colour_count = c->kept_colours;
    w->counters.colouring_kept = 1;
    (void)ga2d__lanes_done(c, extras, round);
    return 1;
}

/* Book-keeping: colours the constraints, in their canonical order, so
   that no two of one colour move the same body (a graph colouring,
   greedy, ga2d__pick_colour; a static, kinematic or sleeping side takes
   no colour, so a pile on one ground does not line up behind it).  A pass solves the colours
   one after the other, and a colour's constraints in any order, or at
   once on several workers: they commute exactly, so every worker count,
   and every lane width, gives the same bits.  Each colour is cut into
   groups of GA2D__LANES in canonical order.  A constraint whose bodies
   have all GA2D__COLOURS between them (a body touching dozens) overflows:
   the overflow's groups come last and run on the calling thread, each
   constraint in the first group with a free lane after the last one that
   moves either of its bodies, so they keep their canonical order.  The
   step's joints take colours in the same masks first
   (ga2d__colour_joints), and a joint that overflows is solved after the
   colours, before the contacts that do.  The solver bodies and the groups
   are sized here; out of memory, the step reports it and solves no
   contact and no joint. */
static void ga2d__assign_lanes(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int used = w->body_used, i, k, extras = 0, overflow = 0, round = 0, count[GA2D__COLOURS], next[GA2D__COLOURS];
    int joints[GA2D__COLOURS], bare[GA2D__COLOURS];
    int *last;
    c->group_count = c->colour_count = 0;
    if (c->constraint_count == 0 && c->joint_active == 0) return;
    if (ga2d__lanes_kept(c)) return;
    c->lane_key_count = -1;
    c->colour_start[0] = c->joint_start[0] = 0;
    if (!ga2d__reserve_sbodies(c) ||
        !ga2d__grow(&w->mem, (void **)&c->colour_masks, &c->colour_mask_capacity, used, sizeof *c->colour_masks) ||
        !ga2d__grow(&w->mem, (void **)&c->joint_colours, &c->joint_colour_capacity, c->joint_active, sizeof *c->joint_colours) ||
        !ga2d__grow(&w->mem, (void **)&c->joint_sorted, &c->joint_sorted_capacity, c->joint_active, sizeof *c->joint_sorted) ||
        !ga2d__grow(&w->mem, (void **)&c->joint_perm, &c->joint_perm_capacity, c->joint_active, sizeof *c->joint_perm)) {
        (void)ga2d__solve_nothing(c);
        return;
    }
    memset(c->colour_masks, 0, (size_t)used * sizeof *c->colour_masks);
    memset(count, 0, sizeof count);
    memset(joints, 0, sizeof joints);
    memset(bare, 0, sizeof bare);
    ga2d__colour_joints(c, joints, bare);
    /* the contacts' colours (held in `lane` until the lanes are put) */
    for (i = 0; i < c->constraint_count; ++i) {
        ga2d__contact_constraint *cc = &c->constraints[i];
        k = ga2d__take_colour(c->colour_masks, cc->a, ga2d__moves_a(cc), cc->b, ga2d__moves_b(cc));
        cc->lane = k;
        if (k == GA2D__OVERFLOW) {
            ++overflow;
            continue;
        }
        ++count[k];
        if (k + 1 > c->colour_count) c->colour_count = k + 1;
    }
    ga2d__sort_joints(c, joints, bare);
    /* each colour's groups, in colour order */
    for (k = 0; k < c->colour_count; ++k) {
        int groups = (count[k] + GA2D__LANES - 1) / GA2D__LANES;
        next[k] = c->colour_start[k];
        c->colour_start[k + 1] = c->colour_start[k] + groups;
        while (c->group_count < c->colour_start[k + 1])
            if (!ga2d__open_group(c)) return;
    }
    last = NULL;
    if (overflow > 0) {
        if (!ga2d__grow(&w->mem, (void **)&c->last_group, &c->last_group_capacity, used, sizeof *c->last_group)) {
            (void)ga2d__solve_nothing(c);
            return;
        }
        last = c->last_group;
        for (i = 0; i < used; ++i) last[i] = -1;
    }
    for (i = 0; i < c->constraint_count; ++i) {
        const ga2d__contact_constraint *cc = &c->constraints[i];
        int gi = c->colour_start[c->colour_count];
        k = cc->lane;
        if (k != GA2D__OVERFLOW) {
            ga2d__lane_put(c, next[k], i);
            if (c->fill[next[k]].count == GA2D__LANES) ++next[k];
        } else {
            int ma = ga2d__moves_a(cc), mb = ga2d__moves_b(cc);
            if (ma && last[cc->a] >= gi) gi = last[cc->a] + 1;
            if (mb && last[cc->b] >= gi) gi = last[cc->b] + 1;
            gi = ga2d__group_free(c, gi);
            if (gi == c->group_count && !ga2d__open_group(c)) return;
            ga2d__lane_put(c, gi, i);
            if (c->fill[gi].count == GA2D__LANES) c->fill[gi].skip = gi + 1;
            if (ma) last[cc->a] = gi;
            if (mb) last[cc->b] = gi;
        }
        ga2d__lane_seen(c, cc, &extras, &round);
    }
    if (ga2d__lanes_done(c, extras, round)) ga2d__keep_lanes(c);
}

/* Stage, over the groups: each learns its count and where its extras
   are, its lanes take their constraints' bodies and data (and what only
   round shapes, conveyors and rolling resistance use, over the anchors
   just written: a polygon world writes none of it), and the lanes it was
   closed without take the dummy slot and all zeros, so their masses are
   zero. */
static void ga2d__fill_groups(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__contact_constraint none;
    int gi, l;
    memset(&none, 0, sizeof none);
    for (gi = begin; gi < end; ++gi) {
        ga2d__group *g = &c->groups[gi];
        g->count = c->fill[gi].count;
        g->extras = g->round = g->conveyor = g->rolling = g->hits = 0;
        g->x = c->group_extras_on ? &c->group_extras[gi] : NULL;
        for (l = g->count; l < GA2D__LANES; ++l) {
            g->a[l] = g->b[l] = w->body_used;
            g->contact[l] = -1;
            GA2D__LANE(g->move_a, l) = GA2D__LANE(g->move_b, l) = 0;
            ga2d__lane_write(g, l, &none, ga2d_vec_make(0, 0), &none);
        }
        if (gi + GA2D__PREFETCH_AHEAD < end) { /* a later group's constraints, from their first field to the last */
            const int *ahead = &c->lane_constraints[(gi + GA2D__PREFETCH_AHEAD) * GA2D__LANES];
            for (l = 0; l < c->fill[gi + GA2D__PREFETCH_AHEAD].count; ++l) {
                GA2D__PREFETCH_READ(&c->constraints[ahead[l]].contact);
                GA2D__PREFETCH_READ(&c->constraints[ahead[l]].p[1].tangent_impulse);
            }
        }
        for (l = 0; l < g->count; ++l) {
            const ga2d__contact_constraint *cc = &c->constraints[c->lane_constraints[gi * GA2D__LANES + l]];
            g->a[l] = cc->a;
            g->b[l] = cc->b;
            g->contact[l] = cc->contact;
            GA2D__LANE(g->move_a, l) = -ga2d__moves_a(cc);
            GA2D__LANE(g->move_b, l) = -ga2d__moves_b(cc);
            ga2d__lane_write(g, l, cc, cc->d, &none);
            if (g->extras || cc->needs_extras) ga2d__lane_extras(g, l, cc, &none);
        }
    }
}

/* Stage, over the moving bodies: their velocities and motion since the
   step began, into the solver bodies, before a run of passes. */
static void ga2d__gather(ga2d__step_context *c, int begin, int end)
{
    /* the arrays in locals: the stores could alias the world's fields,
       and the compiler read them again for every body */
    const ga2d__body *bodies = c->world->bodies;
    const int *moving = c->world->moving;
    ga2d__sbody *sb = c->sbodies;
    int k;
    if (c->group_count == 0 && c->joint_active == 0) return;
    for (k = begin; k < end; ++k) {
        int slot = moving[k];
        const ga2d__body_sim *b = &bodies[slot].sim;
        ga2d_rotor dq = ga2d_rotor_mul(b->q, ga2d_rotor_inverse(b->q0));
        ga2d__sbody s;
        s.vx = b->v.x;
        s.vy = b->v.y;
        s.w = b->w;
        s.pad = 0;
        s.dpx = b->dp.x;
        s.dpy = b->dp.y;
        s.dqc = dq.c;
        s.dqs = dq.s;
        sb[slot] = s;
    }
}

/* Stage, over the moving bodies: the velocities back after them. */
static void ga2d__scatter(ga2d__step_context *c, int begin, int end)
{
    ga2d__body *bodies = c->world->bodies;
    const int *moving = c->world->moving;
    const ga2d__sbody *sb = c->sbodies;
    int k;
    if (c->group_count == 0 && c->joint_active == 0) return;
    for (k = begin; k < end; ++k) {
        int slot = moving[k];
        ga2d__body *b = &bodies[slot];
        const ga2d__sbody *s = &sb[slot];
        if (b->type != GA2D_BODY_DYNAMIC) continue;
        b->sim.v = ga2d_vec_make(s->vx, s->vy);
        b->sim.w = s->w;
    }
}

/* Lane `lane` (group * GA2D__LANES + lane) forgets its impulses (containment). */
static void ga2d__lane_clear(ga2d__step_context *c, int lane)
{
    ga2d__group *g = &c->groups[lane / GA2D__LANES];
    int k;
    for (k = 0; k < 2; ++k) {
        GA2D__LANE(g->nimp[k], lane % GA2D__LANES) = 0;
        GA2D__LANE(g->timp[k], lane % GA2D__LANES) = 0;
    }
    if (g->rolling) GA2D__LANE(g->x->rimp, lane % GA2D__LANES) = 0;
}

/* Stage, over the groups: the accumulated impulses back to the contacts,
   to warm-start the next step (straight to the manifolds: one pass over
   scattered memory, not two). */
static void ga2d__store_impulses(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int gi, l, k;
    for (gi = begin; gi < end; ++gi) {
        const ga2d__group *g = &c->groups[gi];
        if (gi + GA2D__PREFETCH_AHEAD < end) {
            const ga2d__group *next = &c->groups[gi + GA2D__PREFETCH_AHEAD];
            for (l = 0; l < next->count; ++l) { /* the count and the last point's impulses: the ends of what is written */
                ga2d_manifold *m = &w->contacts[next->contact[l]].manifold;
                GA2D__PREFETCH_WRITE(&m->count);
                GA2D__PREFETCH_WRITE(&m->points[1].tangent_impulse);
            }
        }
        for (l = 0; l < g->count; ++l) {
            ga2d_manifold *m = &w->contacts[g->contact[l]].manifold;
            for (k = 0; k < m->count; ++k) {
                m->points[k].normal_impulse = GA2D__LANE(g->nimp[k], l);
                m->points[k].tangent_impulse = GA2D__LANE(g->timp[k], l);
                if (g->hits) w->contacts[g->contact[l]].peak[k] = GA2D__LANE(g->x->npeak[k], l);
            }
        }
    }
}

/* Stage, over the constraints (in order: Gauss-Seidel): non-linear
   Gauss-Seidel moves the bodies apart directly, 0.2 of the
   overlap past slop per pass, at most 0.2 m (in metres) at a time. */
static void ga2d__push_apart(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d_real max_fix = GA2D__NGS_MAX_MOVE * w->def.length_units_per_meter;
    int i, k;
    for (i = begin; i < end; ++i) {
        ga2d__contact_constraint *cc = &c->constraints[i];
        ga2d__body_sim *a = &w->bodies[cc->a].sim, *b = &w->bodies[cc->b].sim;
        for (k = 0; k < cc->count; ++k) {
            ga2d__cpoint *p = &cc->p[k];
            ga2d_vec ra, rb, P;
            ga2d_real s = ga2d__point_now(cc, a, b, p, &ra, &rb), fix = GA2D__NGS_FRACTION * (s + w->slop), lambda;
            fix = fix < -max_fix ? -max_fix : (fix > 0 ? 0 : fix);
            lambda = -ga2d__effective_mass(cc, ra, rb, cc->normal) * fix; /* at the anchors as they are now */
            P = ga2d_vec_scale(cc->normal, lambda);
            /* a body that does not move is not written: P can overflow
               (two huge masses), and inf * 0 would leave a static body's
               centre NaN, where containment (moving bodies) never looks */
            if (cc->inv_ma != 0) {
                a->center = ga2d_vec_sub(a->center, ga2d_vec_scale(P, cc->inv_ma));
                a->dp = ga2d_vec_sub(a->dp, ga2d_vec_scale(P, cc->inv_ma));
            }
            if (cc->inv_mb != 0) {
                b->center = ga2d_vec_add(b->center, ga2d_vec_scale(P, cc->inv_mb));
                b->dp = ga2d_vec_add(b->dp, ga2d_vec_scale(P, cc->inv_mb));
            }
            if (cc->inv_ia != 0) {
                a->q = ga2d__turn(a->q, -cc->inv_ia * ga2d_wedge(ra, P), GA2D_ROTATION_LINEAR);
                a->dq = ga2d_rotor_mul(a->q, ga2d_rotor_inverse(a->q0));
            }
            if (cc->inv_ib != 0) {
                b->q = ga2d__turn(b->q, cc->inv_ib * ga2d_wedge(rb, P), GA2D_ROTATION_LINEAR);
                b->dq = ga2d_rotor_mul(b->q, ga2d_rotor_inverse(b->q0));
            }
        }
    }
}

/* Restitution, as a collision phase before the substeps (sequential
   impulses in the manner of Guendelman and Mirtich): every contact with a
   point that will close its gap within this step or the next substep
   (s + v t - a t^2/2 <= slop, t = dt + h)
   while approaching faster than the threshold collides: its points get the
   impulses that make each leave at e times its impact speed, solved
   together as one block (a flat landing stays flat).  Passes repeat until
   no contact is still colliding (at most 32), so a touching chain passes
   an impact along contact by contact: Newton's cradle.  Energy over the
   gap: a pair still apart by s hits at v_i = sqrt(v^2 + 2 a s) and,
   turned around where it is, leaves at sqrt(e^2 v_i^2 - 2 a s), what it
   would have at height s after a true bounce.  Restitution mixes as the
   larger of the two.  A pass after the first passes over a contact
   neither of whose bodies took an impulse since it last looked: all it
   reads (their velocities, where they are, its own points) is as it was
   when it found nothing to do then, so it would find nothing again; the
   bits are those of looking, and a pile with one bounce in it is not
   looked over 32 times. */
/* Where body b's shapes are after time t, moving as they move now (v,
   w and the free acceleration a). */
static ga2d_transform ga2d__pose_after(const ga2d__body *b, ga2d_vec a, ga2d_real t)
{
    ga2d_vec center = ga2d_vec_add(b->sim.center, ga2d_vec_add(ga2d_vec_scale(b->sim.v, t), ga2d_vec_scale(a, t * t / 2)));
    ga2d_rotor q = ga2d__turn(b->sim.q, b->sim.w * t, GA2D_ROTATION_EXACT);
    return ga2d_transform_make(ga2d_vec_sub(center, ga2d_rotate(q, b->sim.local_center)), q);
}

/* Whether a contact's shapes, moving as they move now, come within slop
   of each other before time `look`: conservative advancement (Mirtich),
   on the shapes' true distance d and its direction n (GJK, from A's
   closest point to B's).  From time t, each body's motion is a straight
   line at its velocity then, plus a turn that moves no point more than
   |w| ext s (ext its reach from its centre) and an acceleration that
   moves none more than |a| s^2 / 2.  The straight part alone moves the
   cores' Minkowski difference along a line, and a point's distance to a
   convex set is convex along a line: it is never below its tangent,
   d + (vB - vA).n s.  Distance moves by at most what a point moves, so
   d(t + s) >= d - u s with u = max(0, -(vB - vA).n) + |wA| ext_A +
   |wB| ext_B + |aB - aA| (look - t) / 2, and the shapes cannot come
   within slop before t + (d - slop) / u.  Only the approach along n
   counts: two discs passing side by side at 100 m/s, 5 cm apart at their
   closest, never meet, and the advance says so in a few steps.  Undecided
   after the iterations, it meets. */
/* Point k's normal mass at its anchors as the step began (the lane
   solver finds its own, per position: ga2d__wfind); only a bounce needs
   this one, so it is found here rather than for every constraint. */
static ga2d_real ga2d__normal_mass(const ga2d__contact_constraint *cc, int k)
{
    return ga2d__effective_mass(cc, cc->p[k].ra, cc->p[k].rb, cc->normal);
}

/* Whether two bodies' shapes (proxies pa, pb), moving as they move now,
   are within slop of each other at time t. */
static int ga2d__within_at(const ga2d_world *w, const ga2d__body *a, const ga2d__body *b, ga2d_vec fa, ga2d_vec fb,
                           const ga2d_shape_proxy *pa, const ga2d_shape_proxy *pb, ga2d_simplex_cache *cache, ga2d_real t)
{
    ga2d_transform xa = ga2d__pose_after(a, fa, t), xb = ga2d__pose_after(b, fb, t);
    return ga2d__distance(pa, pb, ga2d_transform_inv_mul(xa, xb), cache).distance <= w->slop;
}

static int ga2d__meets_within(const ga2d_world *w, const ga2d__contact_constraint *cc, ga2d_real look)
{
    const ga2d__contact *ct = &w->contacts[cc->contact];
    const ga2d__body *a = &w->bodies[cc->a], *b = &w->bodies[cc->b];
    ga2d_shape_proxy pa = ga2d_shape_proxy_of(&w->shapes[ct->shape_a].geom), pb = ga2d_shape_proxy_of(&w->shapes[ct->shape_b].geom);
    ga2d_simplex_cache cache, probe;
    ga2d_vec fa = ga2d__free_accel(w, a), fb = ga2d__free_accel(w, b), dv = ga2d_vec_sub(b->sim.v, a->sim.v),
             df = ga2d_vec_sub(fb, fa);
    ga2d_real spin = GA2D__FABS(a->sim.w) * a->extent + GA2D__FABS(b->sim.w) * b->extent, dfl = ga2d__length(df), t = 0;
    int i;
    cache.count = probe.count = 0;
    for (i = 0; i < GA2D__ADVANCE_ITERATIONS; ++i) {
        ga2d_transform xa = ga2d__pose_after(a, fa, t), xb = ga2d__pose_after(b, fb, t);
        ga2d_distance_result d = ga2d__distance(&pa, &pb, ga2d_transform_inv_mul(xa, xb), &cache);
        ga2d_vec n = ga2d_rotate(xa.q, d.normal), vt = ga2d_vec_add(dv, ga2d_vec_scale(df, t)), gap;
        ga2d_real approach = -ga2d_dot(vt, n), vv = ga2d_dot(vt, vt), s_near = 0, u;
        if (d.distance <= w->slop) return 1;
        /* the closest points themselves, carried on: the straight line
           brings them nearest at s_near (within the look), and turn and
           acceleration move them apart by at most spin s + |a| s^2 / 2 */
        if (approach > 0 && vv > 0) s_near = d.distance * approach / vv < look - t ? d.distance * approach / vv : look - t;
        gap = ga2d_vec_add(ga2d_vec_scale(n, d.distance), ga2d_vec_scale(vt, s_near));
        if (ga2d__length(gap) + spin * s_near + dfl * s_near * s_near / 2 <= w->slop) return 1;
        /* and where the straight approach along n closes the gap (or at
           the look's end): a distance within slop there is a meeting */
        if (approach > 0 && ga2d__within_at(w, a, b, fa, fb, &pa, &pb, &probe, t + d.distance / approach < look ? t + d.distance / approach : look))
            return 1;
        u = (approach > 0 ? approach : 0) + spin + dfl * (look - t) / 2;
        if (!(u > 0)) return 0; /* not closing, turning or accelerating: it never meets */
        t += (d.distance - w->slop) / u;
        if (!(t < look)) return 0;
    }
    return 1;
}

static void ga2d__restitute(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    ga2d_real threshold = w->def.restitution_threshold * w->def.length_units_per_meter;
    ga2d_real h = c->h, look = c->dt + h;
    int i, k, pass, busy = c->bouncy > 0, euler = w->def.integrator == GA2D_INTEGRATOR_SYMPLECTIC_EULER, applied = 0;
    int *kicked = NULL; /* out of memory: reported, and every pass looks at every contact (the same bits) */
    if (busy && ga2d__grow(&w->mem, (void **)&c->kicked, &c->kicked_capacity, w->body_used, sizeof *c->kicked)) {
        kicked = c->kicked;
        memset(kicked, 0, (size_t)w->body_used * sizeof *kicked);
    } else if (busy) {
        c->error = GA2D_ERR_OUT_OF_MEMORY;
    }
    for (pass = 0; pass < GA2D__RESTITUTION_PASSES && busy; ++pass) { /* none bouncy: no pass */
        busy = 0;
        for (i = 0; i < c->constraint_count; ++i) {
            ga2d__contact_constraint *cc = &c->constraints[i];
            ga2d__body *a = &w->bodies[cc->a], *b = &w->bodies[cc->b];
            ga2d_real closing, vn[2], want[2], lambda[2];
            int hit = 0, apart = 1;
            if (cc->restitution == 0) continue;
            if (kicked && pass > 0 && kicked[cc->a] <= cc->seen && kicked[cc->b] <= cc->seen) continue;
            cc->seen = applied;
            closing = -ga2d_dot(ga2d_vec_sub(ga2d__free_accel(w, b), ga2d__free_accel(w, a)), cc->normal);
            closing = closing > 0 ? closing : 0;
            for (k = 0; k < cc->count; ++k) {
                ga2d_real gap = cc->p[k].separation > 0 ? cc->p[k].separation : 0, vi2, leave2;
                /* symplectic Euler's velocity is the one its last drift
                   used, half a kick behind the true one: its modified
                   energy v^2 + 2 g y - g h v is (v - g h/2)^2 + 2 g y up to
                   a constant.  The bounce acts on the true speed, so the
                   flight that follows is e times as fast, not e times
                   less g h, and bounce heights go as e^2n */
                vn[k] = ga2d_dot(ga2d__relative_velocity(&a->sim, &b->sim, cc->p[k].ra, cc->p[k].rb), cc->normal) - (euler ? closing * h / 2 : 0);
                /* closing within the step, or the first substep of the next
                   (the last relax pass brakes a point that is still apart
                   as if a substep followed; the next step would then see a
                   braked approach), or within slop of it, collides now */
                if (vn[k] < -threshold && gap + vn[k] * look - closing * look * look / 2 <= w->slop) hit = 1;
                if (gap <= w->slop) apart = 0;
                vi2 = vn[k] * vn[k] + 2 * closing * gap;
                leave2 = cc->restitution * cc->restitution * vi2 - 2 * closing * gap;
                want[k] = vn[k] < 0 ? (leave2 > 0 ? GA2D__SQRT(leave2) : 0) : vn[k]; /* leaving: as it is */
            }
            /* a pair apart must touch within the step to collide: one
               that does not would bounce off a surface it never meets */
            if (!hit || (apart && !ga2d__meets_within(w, cc, look))) continue;
            busy = 1;
            lambda[0] = lambda[1] = 0;
            if (cc->count == 2 && (vn[0] >= 0 || vn[1] >= 0)) {
                /* a point already leaving is not held to its speed (that
                   would push on it and add energy): only the other collides */
                int j = vn[0] >= 0 ? 1 : 0;
                lambda[j] = want[j] > vn[j] ? (want[j] - vn[j]) * ga2d__normal_mass(cc, j) : 0;
            } else if (cc->count == 2) {
                /* K lambda = want - vn, K_ij = 1/m_a + 1/m_b + (w_ai w_aj)/I_a + (w_bi w_bj)/I_b
                   with w = r ^ n: the points' coupling through the bodies */
                const ga2d__cpoint *p0 = &cc->p[0], *p1 = &cc->p[1];
                ga2d_real k11 = ga2d__coupling(cc, p0->ra, p0->rb, p0->ra, p0->rb);
                ga2d_real k22 = ga2d__coupling(cc, p1->ra, p1->rb, p1->ra, p1->rb);
                ga2d_real k12 = ga2d__coupling(cc, p0->ra, p0->rb, p1->ra, p1->rb);
                ga2d_real det = k11 * k22 - k12 * k12, d0 = want[0] - vn[0], d1 = want[1] - vn[1];
                if (det > GA2D__EPS * 1024 * k11 * k22) {
                    lambda[0] = (k22 * d0 - k12 * d1) / det;
                    lambda[1] = (k11 * d1 - k12 * d0) / det;
                }
                /* a pulling block falls back to the point that must push */
                if (!(det > GA2D__EPS * 1024 * k11 * k22) || lambda[0] < 0 || lambda[1] < 0) {
                    lambda[0] = d0 > 0 ? d0 * ga2d__normal_mass(cc, 0) : 0;
                    lambda[1] = 0;
                    if (d1 * ga2d__normal_mass(cc, 1) > lambda[0]) {
                        lambda[1] = d1 * ga2d__normal_mass(cc, 1);
                        lambda[0] = 0;
                    }
                }
            } else {
                lambda[0] = want[0] > vn[0] ? (want[0] - vn[0]) * ga2d__normal_mass(cc, 0) : 0;
            }
            for (k = 0; k < cc->count; ++k) {
                ga2d__apply_impulse(cc, &a->sim, &b->sim, cc->p[k].ra, cc->p[k].rb, ga2d_vec_scale(cc->normal, lambda[k]));
            }
            /* a side the impulse cannot move (static, kinematic) is not
               marked: its contacts see nothing new from this one */
            if (kicked) {
                ++applied;
                if (cc->inv_ma != 0 || cc->inv_ia != 0) kicked[cc->a] = applied;
                if (cc->inv_mb != 0 || cc->inv_ib != 0) kicked[cc->b] = applied;
            }
        }
    }
    /* passes of a restitution above 1 multiply a speed: one that overflowed
       is contained at once, before user code (an allocator hook as the
       solver's groups grow, the force field) could read it; a second pass
       ran only if the first collided */
    for (k = 0; k < w->moving_count && pass > 1; ++k)
        if (!ga2d__state_finite(&w->bodies[w->moving[k]].sim)) ga2d__contain(w, w->moving[k]);
}

/* ================================================================= joints */
/* Joints live in a pool as bodies and shapes do (ga2d__live_slot), each on
   both its bodies' joint lists: a link is joint << 1 | side (0: A, 1: B),
   a body's list runs newest first.  A joint's creation serial is its
   place in the solver's order, so joints made and destroyed elsewhere
   leave a scene's bits alone. */
static ga2d_joint_id ga2d__joint_id_of(const ga2d_world *w, int k)
{
    ga2d_joint_id id;
    id.index1 = (uint32_t)k + 1;
    id.generation = w->joints[k].generation ^ w->tag;
    return id;
}

/* The live joint an id names, or NULL. */
static ga2d__joint *ga2d__joint_lookup(const ga2d_world *w, ga2d_joint_id id)
{
    return GA2D__LIVE(w, ga2d__joint, joints, joint_used, id);
}

GA2D_API ga2d_joint_id ga2d_joint_id_null(void) { ga2d_joint_id id; id.index1 = 0; id.generation = 0; return id; }
GA2D_API int ga2d_joint_id_is_null(ga2d_joint_id id) { return id.index1 == 0; }
GA2D_API int ga2d_joint_id_equal(ga2d_joint_id a, ga2d_joint_id b) { return a.index1 == b.index1 && a.generation == b.generation; }

/* A body's joint list: its first link, and the link after `link`. */
static int ga2d__first_joint(const ga2d_world *w, int slot) { return w->bodies[slot].joint_head; }
static int ga2d__next_joint(const ga2d_world *w, int link) { return w->joints[link >> 1].next[link & 1]; }
static int ga2d__joint_other(const ga2d_world *w, int link) { return w->joints[link >> 1].body[!(link & 1)]; }

static void ga2d__link_joint(ga2d_world *w, int k, int side)
{
    ga2d__body *b = &w->bodies[w->joints[k].body[side]];
    w->joints[k].next[side] = b->joint_head;
    b->joint_head = k << 1 | side;
}

static void ga2d__unlink_joint(ga2d_world *w, int k, int side)
{
    ga2d__body *b = &w->bodies[w->joints[k].body[side]];
    int *at = &b->joint_head;
    while (*at != (k << 1 | side)) at = &w->joints[*at >> 1].next[*at & 1];
    *at = w->joints[k].next[side];
}

/* Two bodies joined by a joint that keeps their shapes apart
   (collide_connected 0): their pairs are not wanted.  Walks the shorter
   idea of a list: A's (a body has few joints). */
static int ga2d__joined_apart(const ga2d_world *w, int a, int b)
{
    int link;
    for (link = ga2d__first_joint(w, a); link >= 0; link = ga2d__next_joint(w, link))
        if (ga2d__joint_other(w, link) == b && !w->joints[link >> 1].collide_connected) return 1;
    return 0;
}

/* Ends the contacts between bodies a and b (a joint now keeps them apart). */
static void ga2d__end_joined_contacts(ga2d_world *w, int a, int b)
{
    int link = ga2d__first_edge(w, a);
    while (link >= 0) {
        int next = ga2d__next_edge(w, link);
        if (ga2d__edge_other(w, link) == b) ga2d__destroy_contact(w, link >> 1);
        link = next;
    }
}

static void ga2d__joint_free(ga2d_world *w, int k)
{
    ga2d__joint *j = &w->joints[k];
    int s;
    ga2d__unlink_joint(w, k, 0);
    ga2d__unlink_joint(w, k, 1);
    for (s = 0; s < 2; ++s) {
        ga2d__wake(w, j->body[s]);
        if (!j->collide_connected) ga2d__buffer_body(w, j->body[s]); /* pairs they may make again */
    }
    j->type = -1;
    j->generation = ga2d__next_generation(j->generation);
    j->next_free = w->joint_free;
    w->joint_free = k;
    --w->joint_count;
}

/* The checks every joint's def shares: the bodies live, two, one of them
   dynamic; anchors finite and within the coordinate bound. */
static ga2d_result ga2d__joint_bodies_check(const ga2d_world *w, ga2d_body_id a, ga2d_body_id b, ga2d_vec la, ga2d_vec lb)
{
    const ga2d__body *ba = ga2d__lookup(w, a), *bb = ga2d__lookup(w, b);
    if (!ba || !bb) return GA2D_ERR_STALE_ID;
    if (ga2d__slot(a) == ga2d__slot(b) || (ba->type != GA2D_BODY_DYNAMIC && bb->type != GA2D_BODY_DYNAMIC))
        return GA2D_ERR_INVALID_ARGUMENT;
    if (!ga2d__finite_vec(la) || !ga2d__finite_vec(lb)) return GA2D_ERR_NOT_FINITE;
    if (!ga2d__coordinate_ok(la) || !ga2d__coordinate_ok(lb)) return GA2D_ERR_TOO_LARGE;
    return GA2D_OK;
}

/* A revolute def's own numbers: finite, the limit ordered, nothing
   negative that must not be. */
static ga2d_result ga2d__revolute_check(const ga2d_revolute_joint_def *d)
{
    if (!ga2d__finite(d->reference_angle) || !ga2d__finite(d->lower_angle) || !ga2d__finite(d->upper_angle) ||
        !ga2d__finite(d->motor_speed) || !ga2d__finite(d->max_motor_torque) || !ga2d__finite(d->hertz) ||
        !ga2d__finite(d->damping_ratio))
        return GA2D_ERR_NOT_FINITE;
    if (d->max_motor_torque < 0 || d->hertz < 0 || d->damping_ratio < 0 || (d->enable_limit && d->lower_angle > d->upper_angle))
        return GA2D_ERR_INVALID_ARGUMENT;
    return GA2D_OK;
}

GA2D_API ga2d_revolute_joint_def ga2d_default_revolute_joint_def(void)
{
    ga2d_revolute_joint_def d;
    memset(&d, 0, sizeof d);
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

/* A new joint of `type` between two checked bodies, its common fields
   set and the kind's zeroed, linked on both bodies' lists: its slot, or
   -1 when memory runs out (nothing changed).  Inside ga2d__enter. */
static int ga2d__joint_new(ga2d_world *w, int type, ga2d_body_id a, ga2d_body_id b, ga2d_vec la, ga2d_vec lb, int collide,
                           void *user_data)
{
    ga2d__joint *j;
    uint32_t generation;
    int k = w->joint_free >= 0 ? w->joint_free : w->joint_used;
    if (!ga2d__grow(&w->mem, (void **)&w->joints, &w->joint_capacity, k + 1, sizeof *w->joints)) return -1;
    if (k == w->joint_used) {
        w->joints[k].generation = 1;
        ++w->joint_used;
    } else {
        w->joint_free = w->joints[k].next_free;
    }
    j = &w->joints[k];
    generation = j->generation;
    memset(j, 0, sizeof *j);
    j->generation = generation;
    j->type = type;
    j->next_free = -1;
    j->body[0] = ga2d__slot(a);
    j->body[1] = ga2d__slot(b);
    j->serial = ++w->joint_serial;
    j->local[0] = la;
    j->local[1] = lb;
    j->collide_connected = collide != 0;
    j->user_data = user_data;
    ga2d__link_joint(w, k, 0);
    ga2d__link_joint(w, k, 1);
    ++w->joint_count;
    return k;
}

/* A new joint's last steps: contacts it keeps apart end, both bodies
   wake; its id. */
static ga2d_joint_id ga2d__joint_made(ga2d_world *w, int k)
{
    const ga2d__joint *j = &w->joints[k];
    if (!j->collide_connected) ga2d__end_joined_contacts(w, j->body[0], j->body[1]);
    ga2d__wake(w, j->body[0]);
    ga2d__wake(w, j->body[1]);
    return ga2d__joint_id_of(w, k);
}

/* What every create shares: the world writable, the def there, the
   bodies and anchors checked. */
#define GA2D__JOINT_CREATE_CHECK(w, def, out)                                                                          \
    do {                                                                                                               \
        ga2d_result r_ = GA2D_OK;                                                                                      \
        if (out) *(out) = ga2d_joint_id_null();                                                                        \
        if (!(w) || !(def) || !(out)) return GA2D_ERR_INVALID_ARGUMENT;                                                \
        if ((w)->lock) return GA2D_ERR_LOCKED;                                                                         \
        r_ = ga2d__joint_bodies_check(w, (def)->body_a, (def)->body_b, (def)->local_anchor_a, (def)->local_anchor_b);  \
        if (r_ != GA2D_OK) return r_;                                                                                  \
    } while (0)

/* Makes the joint of a checked def: `fill` copies the kind's fields
   into j (a statement on j and def). */
#define GA2D__JOINT_CREATE(w, def, out, type, fill)                                                                    \
    do {                                                                                                               \
        ga2d__joint *j;                                                                                                \
        int k_;                                                                                                        \
        ga2d__enter(w);                                                                                                \
        k_ = ga2d__joint_new(w, type, (def)->body_a, (def)->body_b, (def)->local_anchor_a, (def)->local_anchor_b,      \
                             (def)->collide_connected, (def)->user_data);                                              \
        if (k_ < 0) {                                                                                                  \
            ga2d__leave(w);                                                                                            \
            return GA2D_ERR_OUT_OF_MEMORY;                                                                             \
        }                                                                                                              \
        j = &(w)->joints[k_];                                                                                          \
        fill;                                                                                                          \
        *(out) = ga2d__joint_made(w, k_);                                                                              \
        ga2d__leave(w);                                                                                                \
        return GA2D_OK;                                                                                                \
    } while (0)

static void ga2d__revolute_fill(ga2d__joint *j, const ga2d_revolute_joint_def *def)
{
    j->reference_angle = def->reference_angle;
    j->enable_limit = def->enable_limit != 0;
    j->lower = def->lower_angle;
    j->upper = def->upper_angle;
    j->enable_motor = def->enable_motor != 0;
    j->motor_speed = def->motor_speed;
    j->max_motor = def->max_motor_torque;
    j->enable_spring = def->enable_spring != 0;
    j->hertz = def->hertz;
    j->damping_ratio = def->damping_ratio;
}

GA2D_API ga2d_result ga2d_revolute_joint_create_checked(ga2d_world *w, const ga2d_revolute_joint_def *def, ga2d_joint_id *out)
{
    ga2d_result r;
    GA2D__JOINT_CREATE_CHECK(w, def, out);
    if ((r = ga2d__revolute_check(def)) != GA2D_OK) return r;
    GA2D__JOINT_CREATE(w, def, out, GA2D_JOINT_REVOLUTE, ga2d__revolute_fill(j, def));
}

GA2D_API ga2d_joint_id ga2d_revolute_joint_create(ga2d_world *w, const ga2d_revolute_joint_def *def)
{
    ga2d_joint_id id;
    (void)ga2d_revolute_joint_create_checked(w, def, &id);
    return id;
}

GA2D_API ga2d_result ga2d_joint_destroy(ga2d_world *w, ga2d_joint_id id)
{
    ga2d__joint *j;
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    if (!(j = ga2d__joint_lookup(w, id))) return GA2D_ERR_STALE_ID;
    ga2d__enter(w);
    ga2d__joint_free(w, (int)id.index1 - 1);
    ga2d__leave(w);
    return GA2D_OK;
}

GA2D_API int ga2d_joint_is_valid(const ga2d_world *w, ga2d_joint_id id) { return ga2d__joint_lookup(w, id) != NULL; }

GA2D_API ga2d_joint_type ga2d_joint_get_type(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j ? (ga2d_joint_type)j->type : GA2D_JOINT_TYPE_COUNT;
}

GA2D_API ga2d_body_id ga2d_joint_body_a(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j ? ga2d__id_of(w, j->body[0]) : ga2d_body_id_null();
}

GA2D_API ga2d_body_id ga2d_joint_body_b(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j ? ga2d__id_of(w, j->body[1]) : ga2d_body_id_null();
}

GA2D_API void *ga2d_joint_user_data(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j ? j->user_data : NULL;
}

GA2D_API int ga2d_joint_collide_connected(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j ? j->collide_connected : 0;
}

/* The axial impulses' sum, on B: along the angle (revolute: spring,
   motor, limits; weld and motor joint: the angle's), or along the
   distance joint's axis (its length's or spring's, motor, limits). */
static ga2d_real ga2d__joint_axial_impulse(const ga2d__joint *j)
{
    return j->impulse + j->spring_impulse + j->motor_impulse + j->lower_impulse - j->upper_impulse;
}

/* A distance joint's axis now: unit, from A's anchor to B's (x when they
   coincide). */
static ga2d_vec ga2d__axis_of(ga2d_vec d)
{
    ga2d_real len = ga2d_vec_length(d);
    return len > 0 ? ga2d_vec_scale(d, 1 / len) : ga2d_vec_make(1, 0);
}

static ga2d_vec ga2d__distance_span(const ga2d_world *w, const ga2d__joint *j);
static ga2d_vec ga2d__point_impulse(const ga2d_world *w, const ga2d__joint *j);

/* An impulse of the last substep as a force or torque (impulse / h),
   saturated at the largest real: a huge body's impulse over a tiny
   substep can pass the range, and 0 stays 0 even when 1/h overflowed. */
static ga2d_real ga2d__rate_of(const ga2d_world *w, ga2d_real impulse)
{
    double r = (double)impulse * (double)w->step.inv_h;
    if (impulse == 0 || r != r) return 0;
    return r > (double)GA2D__MAX ? GA2D__MAX : (r < -(double)GA2D__MAX ? -GA2D__MAX : (ga2d_real)r);
}

GA2D_API ga2d_vec ga2d_joint_reaction_force(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    ga2d_vec P, axis;
    if (!j) return ga2d_vec_make(0, 0);
    switch (j->type) {
    case GA2D_JOINT_DISTANCE: P = ga2d_vec_scale(ga2d__axis_of(ga2d__distance_span(w, j)), ga2d__joint_axial_impulse(j)); break;
    case GA2D_JOINT_PRISMATIC:
    case GA2D_JOINT_WHEEL: /* along A's axis, and across it */
        axis = ga2d_rotate(w->bodies[j->body[0]].sim.q, j->offset);
        P = ga2d_vec_add(ga2d_vec_scale(axis, j->spring_impulse + j->lower_impulse - j->upper_impulse +
                                                  (j->type == GA2D_JOINT_PRISMATIC ? j->motor_impulse : 0)),
                         ga2d_vec_scale(ga2d_vec_perp(axis), j->type == GA2D_JOINT_PRISMATIC ? j->linear_impulse.x : j->impulse));
        break;
    default: P = ga2d__point_impulse(w, j); break;
    }
    return ga2d_vec_make(ga2d__rate_of(w, P.x), ga2d__rate_of(w, P.y));
}

GA2D_API ga2d_real ga2d_joint_reaction_torque(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    ga2d_real L;
    if (!j) return 0;
    switch (j->type) {
    case GA2D_JOINT_DISTANCE: L = 0; break;
    case GA2D_JOINT_PRISMATIC: L = j->linear_impulse.y; break;
    case GA2D_JOINT_WHEEL: L = j->motor_impulse; break;
    default: L = ga2d__joint_axial_impulse(j); break;
    }
    return ga2d__rate_of(w, L);
}

/* B's rotor relative to A's (B's turn seen from A), as a unit rotor
   qa~ qb: its angle is angle(B) - angle(A) (2D rotors commute). */
static ga2d_rotor ga2d__relative_rotor(ga2d_rotor qa, ga2d_rotor qb) { return ga2d_rotor_mul(ga2d_rotor_inverse(qa), qb); }

/* An angle moved into (-pi, pi].  Past two turns it is first cut to
   the exact remainder (fmod is exact): steps of 2 pi alone never end
   once 2 pi is below the angle's rounding step (2^26 in float, 2^55 in
   double), and take millions of turns well before that; a revolute or
   weld joint's reference angle, or a motor joint's angular offset, may
   be any finite number (fuzz finding: a reference angle of 1e30 hung the
   step and ga2d_revolute_joint_angle).  Within two turns the bits are
   the steps' as before. */
static ga2d_real ga2d__wrap_angle(ga2d_real a)
{
    if (!(GA2D__FABS(a) <= 4 * GA2D__PI)) a = (ga2d_real)fmod((double)a, 2 * 3.14159265358979323846);
    while (a > GA2D__PI) a -= 2 * GA2D__PI;
    while (a <= -GA2D__PI) a += 2 * GA2D__PI;
    return a;
}

static const ga2d__joint *ga2d__revolute_of(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j && j->type == GA2D_JOINT_REVOLUTE ? j : NULL;
}

GA2D_API ga2d_real ga2d_revolute_joint_angle(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__revolute_of(w, id);
    if (!j) return 0;
    return ga2d__wrap_angle(ga2d_rotor_angle(ga2d__relative_rotor(w->bodies[j->body[0]].sim.q, w->bodies[j->body[1]].sim.q)) -
                            j->reference_angle);
}

GA2D_API ga2d_real ga2d_revolute_joint_speed(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__revolute_of(w, id);
    return j ? w->bodies[j->body[1]].sim.w - w->bodies[j->body[0]].sim.w : 0;
}

GA2D_API ga2d_real ga2d_revolute_joint_motor_torque(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__revolute_of(w, id);
    return j ? ga2d__rate_of(w, j->motor_impulse) : 0;
}

/* A joint of `type` a setter may change (waking its bodies), or why not. */
static ga2d_result ga2d__joint_writable(ga2d_world *w, ga2d_joint_id id, int type, ga2d__joint **out)
{
    ga2d__joint *j;
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    if (!(j = ga2d__joint_lookup(w, id))) return GA2D_ERR_STALE_ID;
    if (j->type != type) return GA2D_ERR_INVALID_ARGUMENT;
    *out = j;
    return GA2D_OK;
}

/* After a setter changed a joint: its bodies wake (from outside a step:
   waking may grow the moving list through the hooks). */
static void ga2d__joint_changed(ga2d_world *w, const ga2d__joint *j)
{
    int a = j->body[0], b = j->body[1];
    ga2d__enter(w);
    ga2d__wake(w, a);
    ga2d__wake(w, b);
    ga2d__leave(w);
}

/* A setter's joint, if it is of `type`, or why not (returned). */
#define GA2D__JOINT_SETTER(w, id, type, j)                                                                             \
    do {                                                                                                               \
        ga2d_result r_ = ga2d__joint_writable(w, id, type, &(j));                                                      \
        if (r_ != GA2D_OK) return r_;                                                                                  \
    } while (0)

/* The setters the kinds with a limit, a motor and a spring share (each
   public one names its kind: a joint of another is refused). */
static ga2d_result ga2d__enable_motor(ga2d_world *w, ga2d_joint_id id, int type, int enable)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, type, j);
    j->enable_motor = enable != 0;
    if (!j->enable_motor) j->motor_impulse = 0;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

static ga2d_result ga2d__set_motor_speed(ga2d_world *w, ga2d_joint_id id, int type, ga2d_real speed)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, type, j);
    if (!ga2d__finite(speed)) return GA2D_ERR_NOT_FINITE;
    j->motor_speed = speed;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

static ga2d_result ga2d__set_max_motor(ga2d_world *w, ga2d_joint_id id, int type, ga2d_real max)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, type, j);
    if (!ga2d__finite(max)) return GA2D_ERR_NOT_FINITE;
    if (max < 0) return GA2D_ERR_INVALID_ARGUMENT;
    j->max_motor = max;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

static ga2d_result ga2d__enable_limit(ga2d_world *w, ga2d_joint_id id, int type, int enable)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, type, j);
    if (enable && j->lower > j->upper) return GA2D_ERR_INVALID_ARGUMENT;
    j->enable_limit = enable != 0;
    if (!j->enable_limit) j->lower_impulse = j->upper_impulse = 0;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

/* lower_min: the least lower bound the kind takes (a distance's 0). */
static ga2d_result ga2d__set_limits(ga2d_world *w, ga2d_joint_id id, int type, ga2d_real lower, ga2d_real upper,
                                    ga2d_real lower_min)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, type, j);
    if (!ga2d__finite(lower) || !ga2d__finite(upper)) return GA2D_ERR_NOT_FINITE;
    if (lower > upper || lower < lower_min) return GA2D_ERR_INVALID_ARGUMENT;
    j->lower = lower;
    j->upper = upper;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

static ga2d_result ga2d__enable_spring(ga2d_world *w, ga2d_joint_id id, int type, int enable)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, type, j);
    j->enable_spring = enable != 0;
    j->spring_impulse = 0;
    if (type == GA2D_JOINT_DISTANCE) j->impulse = 0; /* the rigid length's, or the spring's: one of them acts */
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

/* A spring's hertz and damping ratio; `linear`: the weld's linear one
   (else the kind's spring, the weld's angular one). */
static ga2d_result ga2d__set_spring(ga2d_world *w, ga2d_joint_id id, int type, ga2d_real hertz, ga2d_real damping_ratio,
                                    int linear)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, type, j);
    if (!ga2d__finite(hertz) || !ga2d__finite(damping_ratio)) return GA2D_ERR_NOT_FINITE;
    if (hertz < 0 || damping_ratio < 0) return GA2D_ERR_INVALID_ARGUMENT;
    if (linear) {
        j->linear_hertz = hertz;
        j->linear_damping_ratio = damping_ratio;
    } else {
        j->hertz = hertz;
        j->damping_ratio = damping_ratio;
    }
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

/* no lower bound: an angle's limit may be any angle */
#define GA2D__NO_LOWER_BOUND (-GA2D__MAX)

GA2D_API ga2d_result ga2d_revolute_joint_enable_motor(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_motor(w, id, GA2D_JOINT_REVOLUTE, enable);
}

GA2D_API ga2d_result ga2d_revolute_joint_set_motor_speed(ga2d_world *w, ga2d_joint_id id, ga2d_real speed)
{
    return ga2d__set_motor_speed(w, id, GA2D_JOINT_REVOLUTE, speed);
}

GA2D_API ga2d_result ga2d_revolute_joint_set_max_motor_torque(ga2d_world *w, ga2d_joint_id id, ga2d_real torque)
{
    return ga2d__set_max_motor(w, id, GA2D_JOINT_REVOLUTE, torque);
}

GA2D_API ga2d_result ga2d_revolute_joint_enable_limit(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_limit(w, id, GA2D_JOINT_REVOLUTE, enable);
}

GA2D_API ga2d_result ga2d_revolute_joint_set_limits(ga2d_world *w, ga2d_joint_id id, ga2d_real lower, ga2d_real upper)
{
    return ga2d__set_limits(w, id, GA2D_JOINT_REVOLUTE, lower, upper, GA2D__NO_LOWER_BOUND);
}

GA2D_API ga2d_result ga2d_revolute_joint_enable_spring(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_spring(w, id, GA2D_JOINT_REVOLUTE, enable);
}

GA2D_API ga2d_result ga2d_revolute_joint_set_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio)
{
    return ga2d__set_spring(w, id, GA2D_JOINT_REVOLUTE, hertz, damping_ratio, 0);
}

/* ------------------------------------------------ distance, weld, motor */
static ga2d_result ga2d__distance_check(const ga2d_distance_joint_def *d)
{
    if (!ga2d__finite(d->length) || !ga2d__finite(d->min_length) || !ga2d__finite(d->max_length) || !ga2d__finite(d->hertz) ||
        !ga2d__finite(d->damping_ratio) || !ga2d__finite(d->motor_speed) || !ga2d__finite(d->max_motor_force))
        return GA2D_ERR_NOT_FINITE;
    if (!(d->length > 0) || d->min_length < 0 || d->min_length > d->max_length || d->hertz < 0 || d->damping_ratio < 0 ||
        d->max_motor_force < 0)
        return GA2D_ERR_INVALID_ARGUMENT;
    return GA2D_OK;
}

GA2D_API ga2d_distance_joint_def ga2d_default_distance_joint_def(void)
{
    ga2d_distance_joint_def d;
    memset(&d, 0, sizeof d);
    d.length = 1;
    d.max_length = GA2D__R(1e6);
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

static void ga2d__distance_fill(ga2d__joint *j, const ga2d_distance_joint_def *def)
{
    j->length = def->length;
    j->enable_limit = def->enable_limit != 0;
    j->lower = def->min_length;
    j->upper = def->max_length;
    j->enable_spring = def->enable_spring != 0;
    j->hertz = def->hertz;
    j->damping_ratio = def->damping_ratio;
    j->enable_motor = def->enable_motor != 0;
    j->motor_speed = def->motor_speed;
    j->max_motor = def->max_motor_force;
}

GA2D_API ga2d_result ga2d_distance_joint_create_checked(ga2d_world *w, const ga2d_distance_joint_def *def, ga2d_joint_id *out)
{
    ga2d_result r;
    GA2D__JOINT_CREATE_CHECK(w, def, out);
    if ((r = ga2d__distance_check(def)) != GA2D_OK) return r;
    GA2D__JOINT_CREATE(w, def, out, GA2D_JOINT_DISTANCE, ga2d__distance_fill(j, def));
}

GA2D_API ga2d_joint_id ga2d_distance_joint_create(ga2d_world *w, const ga2d_distance_joint_def *def)
{
    ga2d_joint_id id;
    (void)ga2d_distance_joint_create_checked(w, def, &id);
    return id;
}

static ga2d_result ga2d__weld_check(const ga2d_weld_joint_def *d)
{
    if (!ga2d__finite(d->reference_angle) || !ga2d__finite(d->linear_hertz) || !ga2d__finite(d->angular_hertz) ||
        !ga2d__finite(d->linear_damping_ratio) || !ga2d__finite(d->angular_damping_ratio))
        return GA2D_ERR_NOT_FINITE;
    if (d->linear_hertz < 0 || d->angular_hertz < 0 || d->linear_damping_ratio < 0 || d->angular_damping_ratio < 0)
        return GA2D_ERR_INVALID_ARGUMENT;
    return GA2D_OK;
}

GA2D_API ga2d_weld_joint_def ga2d_default_weld_joint_def(void)
{
    ga2d_weld_joint_def d;
    memset(&d, 0, sizeof d);
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

static void ga2d__weld_fill(ga2d__joint *j, const ga2d_weld_joint_def *def)
{
    j->reference_angle = def->reference_angle;
    j->linear_hertz = def->linear_hertz;
    j->linear_damping_ratio = def->linear_damping_ratio;
    j->hertz = def->angular_hertz;
    j->damping_ratio = def->angular_damping_ratio;
}

GA2D_API ga2d_result ga2d_weld_joint_create_checked(ga2d_world *w, const ga2d_weld_joint_def *def, ga2d_joint_id *out)
{
    ga2d_result r;
    GA2D__JOINT_CREATE_CHECK(w, def, out);
    if ((r = ga2d__weld_check(def)) != GA2D_OK) return r;
    GA2D__JOINT_CREATE(w, def, out, GA2D_JOINT_WELD, ga2d__weld_fill(j, def));
}

GA2D_API ga2d_joint_id ga2d_weld_joint_create(ga2d_world *w, const ga2d_weld_joint_def *def)
{
    ga2d_joint_id id;
    (void)ga2d_weld_joint_create_checked(w, def, &id);
    return id;
}

static ga2d_result ga2d__motor_check(const ga2d_motor_joint_def *d)
{
    if (!ga2d__finite_vec(d->linear_offset) || !ga2d__finite(d->angular_offset) || !ga2d__finite(d->max_force) ||
        !ga2d__finite(d->max_torque) || !ga2d__finite(d->correction_factor))
        return GA2D_ERR_NOT_FINITE;
    if (d->max_force < 0 || d->max_torque < 0 || d->correction_factor < 0 || d->correction_factor > 1)
        return GA2D_ERR_INVALID_ARGUMENT;
    return ga2d__coordinate_ok(d->linear_offset) ? GA2D_OK : GA2D_ERR_TOO_LARGE;
}

GA2D_API ga2d_motor_joint_def ga2d_default_motor_joint_def(void)
{
    ga2d_motor_joint_def d;
    memset(&d, 0, sizeof d);
    d.max_force = 1;
    d.max_torque = 1;
    d.correction_factor = GA2D__R(0.3);
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

static void ga2d__motor_fill(ga2d__joint *j, const ga2d_motor_joint_def *def)
{
    j->offset = def->linear_offset;
    j->reference_angle = def->angular_offset;
    j->max_force = def->max_force;
    j->max_torque = def->max_torque;
    j->correction = def->correction_factor;
}

GA2D_API ga2d_result ga2d_motor_joint_create_checked(ga2d_world *w, const ga2d_motor_joint_def *def, ga2d_joint_id *out)
{
    ga2d_result r;
    GA2D__JOINT_CREATE_CHECK(w, def, out);
    if ((r = ga2d__motor_check(def)) != GA2D_OK) return r;
    GA2D__JOINT_CREATE(w, def, out, GA2D_JOINT_MOTOR, ga2d__motor_fill(j, def));
}

GA2D_API ga2d_joint_id ga2d_motor_joint_create(ga2d_world *w, const ga2d_motor_joint_def *def)
{
    ga2d_joint_id id;
    (void)ga2d_motor_joint_create_checked(w, def, &id);
    return id;
}

/* The distance joint's anchors' offset now, B's from A's (world frame),
   from the bodies' poses. */
static ga2d_vec ga2d__distance_span(const ga2d_world *w, const ga2d__joint *j)
{
    const ga2d__body *a = &w->bodies[j->body[0]], *b = &w->bodies[j->body[1]];
    return ga2d_vec_sub(ga2d_vec_add(ga2d__body_origin(b), ga2d_rotate(b->sim.q, j->local[1])),
                        ga2d_vec_add(ga2d__body_origin(a), ga2d_rotate(a->sim.q, j->local[0])));
}

GA2D_API ga2d_real ga2d_distance_joint_current_length(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j && j->type == GA2D_JOINT_DISTANCE ? ga2d_vec_length(ga2d__distance_span(w, j)) : 0;
}

GA2D_API ga2d_result ga2d_distance_joint_set_length(ga2d_world *w, ga2d_joint_id id, ga2d_real length)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, GA2D_JOINT_DISTANCE, j);
    if (!ga2d__finite(length)) return GA2D_ERR_NOT_FINITE;
    if (!(length > 0)) return GA2D_ERR_INVALID_ARGUMENT;
    j->length = length;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_distance_joint_enable_limit(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_limit(w, id, GA2D_JOINT_DISTANCE, enable);
}

GA2D_API ga2d_result ga2d_distance_joint_set_length_range(ga2d_world *w, ga2d_joint_id id, ga2d_real min_length, ga2d_real max_length)
{
    return ga2d__set_limits(w, id, GA2D_JOINT_DISTANCE, min_length, max_length, 0);
}

GA2D_API ga2d_result ga2d_distance_joint_enable_spring(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_spring(w, id, GA2D_JOINT_DISTANCE, enable);
}

GA2D_API ga2d_result ga2d_distance_joint_set_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio)
{
    return ga2d__set_spring(w, id, GA2D_JOINT_DISTANCE, hertz, damping_ratio, 0);
}

GA2D_API ga2d_result ga2d_distance_joint_enable_motor(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_motor(w, id, GA2D_JOINT_DISTANCE, enable);
}

GA2D_API ga2d_result ga2d_distance_joint_set_motor_speed(ga2d_world *w, ga2d_joint_id id, ga2d_real speed)
{
    return ga2d__set_motor_speed(w, id, GA2D_JOINT_DISTANCE, speed);
}

GA2D_API ga2d_result ga2d_distance_joint_set_max_motor_force(ga2d_world *w, ga2d_joint_id id, ga2d_real force)
{
    return ga2d__set_max_motor(w, id, GA2D_JOINT_DISTANCE, force);
}

GA2D_API ga2d_result ga2d_weld_joint_set_linear_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio)
{
    return ga2d__set_spring(w, id, GA2D_JOINT_WELD, hertz, damping_ratio, 1);
}

GA2D_API ga2d_result ga2d_weld_joint_set_angular_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio)
{
    return ga2d__set_spring(w, id, GA2D_JOINT_WELD, hertz, damping_ratio, 0);
}

GA2D_API ga2d_result ga2d_motor_joint_set_linear_offset(ga2d_world *w, ga2d_joint_id id, ga2d_vec offset)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, GA2D_JOINT_MOTOR, j);
    if (!ga2d__finite_vec(offset)) return GA2D_ERR_NOT_FINITE;
    if (!ga2d__coordinate_ok(offset)) return GA2D_ERR_TOO_LARGE;
    j->offset = offset;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_motor_joint_set_angular_offset(ga2d_world *w, ga2d_joint_id id, ga2d_real offset)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, GA2D_JOINT_MOTOR, j);
    if (!ga2d__finite(offset)) return GA2D_ERR_NOT_FINITE;
    j->reference_angle = offset;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_motor_joint_set_max_force(ga2d_world *w, ga2d_joint_id id, ga2d_real force)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, GA2D_JOINT_MOTOR, j);
    if (!ga2d__finite(force)) return GA2D_ERR_NOT_FINITE;
    if (force < 0) return GA2D_ERR_INVALID_ARGUMENT;
    j->max_force = force;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_motor_joint_set_max_torque(ga2d_world *w, ga2d_joint_id id, ga2d_real torque)
{
    ga2d__joint *j;
    GA2D__JOINT_SETTER(w, id, GA2D_JOINT_MOTOR, j);
    if (!ga2d__finite(torque)) return GA2D_ERR_NOT_FINITE;
    if (torque < 0) return GA2D_ERR_INVALID_ARGUMENT;
    j->max_torque = torque;
    ga2d__joint_changed(w, j);
    return GA2D_OK;
}

/* --------------------------------------------------- prismatic and wheel */
/* An axis in A's frame as the def gives it: finite, not zero (made unit
   when the joint is made). */
static ga2d_result ga2d__axis_check(ga2d_vec axis)
{
    if (!ga2d__finite_vec(axis)) return GA2D_ERR_NOT_FINITE;
    return ga2d_vec_length(axis) > 0 ? GA2D_OK : GA2D_ERR_INVALID_ARGUMENT;
}

/* What a limit, a motor and a spring ask of their numbers. */
static ga2d_result ga2d__drive_check(int enable_limit, ga2d_real lower, ga2d_real upper, ga2d_real speed, ga2d_real max_motor,
                                     ga2d_real hertz, ga2d_real damping_ratio)
{
    if (!ga2d__finite(lower) || !ga2d__finite(upper) || !ga2d__finite(speed) || !ga2d__finite(max_motor) ||
        !ga2d__finite(hertz) || !ga2d__finite(damping_ratio))
        return GA2D_ERR_NOT_FINITE;
    if (max_motor < 0 || hertz < 0 || damping_ratio < 0 || (enable_limit && lower > upper)) return GA2D_ERR_INVALID_ARGUMENT;
    return GA2D_OK;
}

GA2D_API ga2d_prismatic_joint_def ga2d_default_prismatic_joint_def(void)
{
    ga2d_prismatic_joint_def d;
    memset(&d, 0, sizeof d);
    d.local_axis_a = ga2d_vec_make(1, 0);
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

static void ga2d__prismatic_fill(ga2d__joint *j, const ga2d_prismatic_joint_def *def)
{
    j->offset = ga2d_vec_scale(def->local_axis_a, 1 / ga2d_vec_length(def->local_axis_a));
    j->reference_angle = def->reference_angle;
    j->enable_limit = def->enable_limit != 0;
    j->lower = def->lower_translation;
    j->upper = def->upper_translation;
    j->enable_motor = def->enable_motor != 0;
    j->motor_speed = def->motor_speed;
    j->max_motor = def->max_motor_force;
    j->enable_spring = def->enable_spring != 0;
    j->hertz = def->hertz;
    j->damping_ratio = def->damping_ratio;
}

GA2D_API ga2d_result ga2d_prismatic_joint_create_checked(ga2d_world *w, const ga2d_prismatic_joint_def *def, ga2d_joint_id *out)
{
    ga2d_result r;
    GA2D__JOINT_CREATE_CHECK(w, def, out);
    if ((r = ga2d__axis_check(def->local_axis_a)) != GA2D_OK) return r;
    if (!ga2d__finite(def->reference_angle)) return GA2D_ERR_NOT_FINITE;
    if ((r = ga2d__drive_check(def->enable_limit, def->lower_translation, def->upper_translation, def->motor_speed,
                               def->max_motor_force, def->hertz, def->damping_ratio)) != GA2D_OK)
        return r;
    GA2D__JOINT_CREATE(w, def, out, GA2D_JOINT_PRISMATIC, ga2d__prismatic_fill(j, def));
}

GA2D_API ga2d_joint_id ga2d_prismatic_joint_create(ga2d_world *w, const ga2d_prismatic_joint_def *def)
{
    ga2d_joint_id id;
    (void)ga2d_prismatic_joint_create_checked(w, def, &id);
    return id;
}

GA2D_API ga2d_wheel_joint_def ga2d_default_wheel_joint_def(void)
{
    ga2d_wheel_joint_def d;
    memset(&d, 0, sizeof d);
    d.local_axis_a = ga2d_vec_make(0, 1);
    d.enable_spring = 1;
    d.hertz = 1;
    d.damping_ratio = GA2D__R(0.7);
    d.internal_cookie = GA2D_DEF_COOKIE;
    return d;
}

static void ga2d__wheel_fill(ga2d__joint *j, const ga2d_wheel_joint_def *def)
{
    j->offset = ga2d_vec_scale(def->local_axis_a, 1 / ga2d_vec_length(def->local_axis_a));
    j->enable_spring = def->enable_spring != 0;
    j->hertz = def->hertz;
    j->damping_ratio = def->damping_ratio;
    j->enable_limit = def->enable_limit != 0;
    j->lower = def->lower_translation;
    j->upper = def->upper_translation;
    j->enable_motor = def->enable_motor != 0;
    j->motor_speed = def->motor_speed;
    j->max_motor = def->max_motor_torque;
}

GA2D_API ga2d_result ga2d_wheel_joint_create_checked(ga2d_world *w, const ga2d_wheel_joint_def *def, ga2d_joint_id *out)
{
    ga2d_result r;
    GA2D__JOINT_CREATE_CHECK(w, def, out);
    if ((r = ga2d__axis_check(def->local_axis_a)) != GA2D_OK) return r;
    if ((r = ga2d__drive_check(def->enable_limit, def->lower_translation, def->upper_translation, def->motor_speed,
                               def->max_motor_torque, def->hertz, def->damping_ratio)) != GA2D_OK)
        return r;
    GA2D__JOINT_CREATE(w, def, out, GA2D_JOINT_WHEEL, ga2d__wheel_fill(j, def));
}

GA2D_API ga2d_joint_id ga2d_wheel_joint_create(ga2d_world *w, const ga2d_wheel_joint_def *def)
{
    ga2d_joint_id id;
    (void)ga2d_wheel_joint_create_checked(w, def, &id);
    return id;
}

/* A slider's (prismatic, wheel) translation and its rate now, from the
   bodies: along A's axis, B's anchor from A's; d/dt (axis . d) = w_a
   (axis_perp . d) + axis . (v_b + w_b rb_perp - v_a - w_a ra_perp). */
static ga2d_real ga2d__slider_now(const ga2d_world *w, const ga2d__joint *j, ga2d_real *rate)
{
    const ga2d__body *a = &w->bodies[j->body[0]], *b = &w->bodies[j->body[1]];
    ga2d_vec axis = ga2d_rotate(a->sim.q, j->offset), d = ga2d__distance_span(w, j);
    ga2d_vec ra = ga2d_rotate(a->sim.q, ga2d_vec_sub(j->local[0], a->sim.local_center));
    ga2d_vec rb = ga2d_rotate(b->sim.q, ga2d_vec_sub(j->local[1], b->sim.local_center));
    ga2d_vec vr = ga2d_vec_sub(ga2d_vec_add(b->sim.v, ga2d_vec_scale(ga2d_vec_perp(rb), b->sim.w)),
                               ga2d_vec_add(a->sim.v, ga2d_vec_scale(ga2d_vec_perp(ra), a->sim.w)));
    if (rate) *rate = a->sim.w * ga2d_dot(ga2d_vec_perp(axis), d) + ga2d_dot(axis, vr);
    return ga2d_dot(axis, d);
}

GA2D_API ga2d_real ga2d_prismatic_joint_translation(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j && j->type == GA2D_JOINT_PRISMATIC ? ga2d__slider_now(w, j, NULL) : 0;
}

GA2D_API ga2d_real ga2d_prismatic_joint_speed(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    ga2d_real rate = 0;
    if (j && j->type == GA2D_JOINT_PRISMATIC) (void)ga2d__slider_now(w, j, &rate);
    return rate;
}

GA2D_API ga2d_real ga2d_wheel_joint_translation(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j && j->type == GA2D_JOINT_WHEEL ? ga2d__slider_now(w, j, NULL) : 0;
}

GA2D_API ga2d_real ga2d_wheel_joint_motor_torque(const ga2d_world *w, ga2d_joint_id id)
{
    const ga2d__joint *j = ga2d__joint_lookup(w, id);
    return j && j->type == GA2D_JOINT_WHEEL ? ga2d__rate_of(w, j->motor_impulse) : 0;
}

#define GA2D__P GA2D_JOINT_PRISMATIC
#define GA2D__WH GA2D_JOINT_WHEEL
GA2D_API ga2d_result ga2d_prismatic_joint_enable_limit(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_limit(w, id, GA2D__P, enable);
}
GA2D_API ga2d_result ga2d_prismatic_joint_set_limits(ga2d_world *w, ga2d_joint_id id, ga2d_real lower, ga2d_real upper)
{
    return ga2d__set_limits(w, id, GA2D__P, lower, upper, GA2D__NO_LOWER_BOUND);
}
GA2D_API ga2d_result ga2d_prismatic_joint_enable_motor(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_motor(w, id, GA2D__P, enable);
}
GA2D_API ga2d_result ga2d_prismatic_joint_set_motor_speed(ga2d_world *w, ga2d_joint_id id, ga2d_real speed)
{
    return ga2d__set_motor_speed(w, id, GA2D__P, speed);
}
GA2D_API ga2d_result ga2d_prismatic_joint_set_max_motor_force(ga2d_world *w, ga2d_joint_id id, ga2d_real force)
{
    return ga2d__set_max_motor(w, id, GA2D__P, force);
}
GA2D_API ga2d_result ga2d_prismatic_joint_enable_spring(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_spring(w, id, GA2D__P, enable);
}
GA2D_API ga2d_result ga2d_prismatic_joint_set_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio)
{
    return ga2d__set_spring(w, id, GA2D__P, hertz, damping_ratio, 0);
}
GA2D_API ga2d_result ga2d_wheel_joint_enable_spring(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_spring(w, id, GA2D__WH, enable);
}
GA2D_API ga2d_result ga2d_wheel_joint_set_spring(ga2d_world *w, ga2d_joint_id id, ga2d_real hertz, ga2d_real damping_ratio)
{
    return ga2d__set_spring(w, id, GA2D__WH, hertz, damping_ratio, 0);
}
GA2D_API ga2d_result ga2d_wheel_joint_enable_limit(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_limit(w, id, GA2D__WH, enable);
}
GA2D_API ga2d_result ga2d_wheel_joint_set_limits(ga2d_world *w, ga2d_joint_id id, ga2d_real lower, ga2d_real upper)
{
    return ga2d__set_limits(w, id, GA2D__WH, lower, upper, GA2D__NO_LOWER_BOUND);
}
GA2D_API ga2d_result ga2d_wheel_joint_enable_motor(ga2d_world *w, ga2d_joint_id id, int enable)
{
    return ga2d__enable_motor(w, id, GA2D__WH, enable);
}
GA2D_API ga2d_result ga2d_wheel_joint_set_motor_speed(ga2d_world *w, ga2d_joint_id id, ga2d_real speed)
{
    return ga2d__set_motor_speed(w, id, GA2D__WH, speed);
}
GA2D_API ga2d_result ga2d_wheel_joint_set_max_motor_torque(ga2d_world *w, ga2d_joint_id id, ga2d_real torque)
{
    return ga2d__set_max_motor(w, id, GA2D__WH, torque);
}
#undef GA2D__P
#undef GA2D__WH

GA2D_API ga2d_vec ga2d_body_local_point(const ga2d_world *w, ga2d_body_id id, ga2d_vec world_point)
{
    const ga2d__body *b = ga2d__lookup(w, id);
    if (!b) return ga2d_vec_make(0, 0);
    return ga2d_rotate_inv(b->sim.q, ga2d_vec_sub(world_point, ga2d__body_origin(b)));
}

/* ---------------------------------------------------------- joint solver */
/* What the step's listing needs of a joint slot, found on the workers
   (ga2d__see_joints) so that the listing itself reads one small array in
   order, not every joint's record and its two bodies'. */
enum { GA2D__JOINT_GONE, GA2D__JOINT_AWAKE, GA2D__JOINT_ASLEEP };
struct ga2d__joint_seen {
    uint64_t serial;
    int state; /* GA2D__JOINT_*: free slot; an awake dynamic body; neither */
};

/* Stage, over the joint slots: each one's state and serial. */
static void ga2d__see_joints(ga2d__step_context *c, int begin, int end)
{
    const ga2d_world *w = c->world;
    int k;
    for (k = begin; k < end; ++k) {
        const ga2d__joint *j = &w->joints[k];
        ga2d__joint_seen *seen = &c->joint_seen[k];
        const ga2d__body *a, *b;
        if (j->type < 0) {
            seen->state = GA2D__JOINT_GONE;
            continue;
        }
        a = &w->bodies[j->body[0]];
        b = &w->bodies[j->body[1]];
        seen->serial = j->serial;
        seen->state = (a->type == GA2D_BODY_DYNAMIC && a->awake) || (b->type == GA2D_BODY_DYNAMIC && b->awake)
                          ? GA2D__JOINT_AWAKE
                          : GA2D__JOINT_ASLEEP;
    }
}

/* The step's joints: those with an awake dynamic body, in creation order
   (insertion sort on the serial: the pool's order is nearly that, so
   this is about one pass).  Out of memory: the step reports it and no
   joint is solved. */
static void ga2d__order_joints(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    const ga2d__joint_seen *seen;
    int k, n = 0;
    uint64_t last = 0; /* the largest serial listed */
    c->joint_active = 0;
    if (w->joint_count == 0) return;
    if (!ga2d__grow(&w->mem, (void **)&c->joint_order, &c->joint_order_capacity, w->joint_count, sizeof *c->joint_order) ||
        !ga2d__grow(&w->mem, (void **)&c->joint_keys, &c->joint_key_capacity, w->joint_count, sizeof *c->joint_keys) ||
        !ga2d__grow(&w->mem, (void **)&c->joint_seen, &c->joint_seen_capacity, w->joint_used, sizeof *c->joint_seen)) {
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return;
    }
    ga2d__run_split(c, ga2d__see_joints, w->joint_used);
    seen = c->joint_seen;
    for (k = 0; k < w->joint_used; ++k) {
        int at;
        if (seen[k].state == GA2D__JOINT_GONE) continue;
        if (seen[k].state == GA2D__JOINT_ASLEEP) {
            /* asleep on a kinematic body that moves: woken at the step's
               end (ga2d__grant_wakes), carried from the next step on */
            const ga2d__joint *j = &w->joints[k];
            ga2d__body *a = &w->bodies[j->body[0]], *b = &w->bodies[j->body[1]];
            ga2d__body *sleeper = a->type == GA2D_BODY_DYNAMIC ? a : b;
            const ga2d__body *carrier = sleeper == a ? b : a;
            if (carrier->type == GA2D_BODY_KINEMATIC && (carrier->sim.v.x != 0 || carrier->sim.v.y != 0 || carrier->sim.w != 0))
                (void)ga2d__field_wakes(w, sleeper, 1);
            continue;
        }
        if (seen[k].serial > last) { /* the pool's order is nearly creation order */
            c->joint_order[n++] = k;
            last = seen[k].serial;
            continue;
        }
        for (at = n; at > 0 && seen[c->joint_order[at - 1]].serial > seen[k].serial; --at) c->joint_order[at] = c->joint_order[at - 1];
        c->joint_order[at] = k;
        ++n;
    }
    c->joint_active = n;
}

/* A joint's impulses go (no warm start, or its body was contained). */
static void ga2d__joint_forget(ga2d__joint *j)
{
    j->linear_impulse = ga2d_vec_make(0, 0);
    j->spring_impulse = j->motor_impulse = j->lower_impulse = j->upper_impulse = j->impulse = 0;
}

/* A joint spring's hertz, capped at a quarter of the substep rate (0:
   none). */
static ga2d_real ga2d__joint_hertz(const ga2d__step_context *c, ga2d_real hertz)
{
    return hertz < GA2D__HERTZ_CAP * c->inv_h ? hertz : GA2D__HERTZ_CAP * c->inv_h;
}

/* Whether a joint's passes read its angle (ga2d__joint_angle). */
static int ga2d__reads_angle(const ga2d__joint *j)
{
    switch (j->type) {
    case GA2D_JOINT_REVOLUTE: return j->enable_spring || j->enable_limit;
    case GA2D_JOINT_DISTANCE:
    case GA2D_JOINT_WHEEL: return 0;
    default: return 1;
    }
}

/* Stage, over the step's joints, before they are coloured: anchors,
   masses and the angle where the step began. */
static void ga2d__prepare_joints(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int i;
    for (i = begin; i < end; ++i) {
        ga2d__joint *j = &w->joints[c->joint_order[i]];
        const ga2d__body *a = &w->bodies[j->body[0]], *b = &w->bodies[j->body[1]];
        int ma = a->type == GA2D_BODY_DYNAMIC && a->awake, mb = b->type == GA2D_BODY_DYNAMIC && b->awake;
        j->ra = ga2d_rotate(a->sim.q, ga2d_vec_sub(j->local[0], a->sim.local_center));
        j->rb = ga2d_rotate(b->sim.q, ga2d_vec_sub(j->local[1], b->sim.local_center));
        j->delta_center = ga2d_vec_sub(b->sim.center, a->sim.center);
        /* the angle (two arctangents) only where a pass reads it: a bare
           hinge or a distance or wheel joint never does */
        j->delta_angle = ga2d__reads_angle(j) ? ga2d__wrap_angle(ga2d_rotor_angle(ga2d__relative_rotor(a->sim.q, b->sim.q)) - j->reference_angle) : 0;
        j->ima = ma ? a->sim.inv_mass : 0;
        j->imb = mb ? b->sim.inv_mass : 0;
        j->iia = ma ? a->sim.inv_inertia : 0;
        j->iib = mb ? b->sim.inv_inertia : 0;
        j->axial_mass = j->iia + j->iib > 0 ? 1 / (j->iia + j->iib) : 0;
        ga2d__joint_key(j, &c->joint_keys[i]); /* for ga2d__lanes_kept, read here while j is at hand */
        /* a spring asked stiffer than a quarter of the substep rate is
           made at that rate (as contacts are): stiffer, the one biased
           pass a substep rings and grows */
        j->spring = ga2d__make_soft(ga2d__joint_hertz(c, j->enable_spring || j->type == GA2D_JOINT_WELD ? j->hertz : 0),
                                    j->damping_ratio, c->h);
        j->linear_spring = ga2d__make_soft(ga2d__joint_hertz(c, j->linear_hertz), j->linear_damping_ratio, c->h);
        j->target = ga2d_rotate(a->sim.q, j->offset);
        if (!w->def.enable_warm_starting) ga2d__joint_forget(j);
    }
}

/* A solver body's velocity state, and a turn applied to an anchor. */
typedef struct ga2d__jbody { ga2d_vec v; ga2d_real w; } ga2d__jbody;

static GA2D__HOT ga2d__jbody ga2d__jload(const ga2d__sbody *s)
{
    ga2d__jbody b;
    b.v = ga2d_vec_make(s->vx, s->vy);
    b.w = s->w;
    return b;
}

static GA2D__HOT void ga2d__jstore(ga2d__sbody *s, ga2d__jbody b)
{
    s->vx = b.v.x;
    s->vy = b.v.y;
    s->w = b.w;
}

/* Both sides back, but only a side the joint moves: a body it does not
   move (static, kinematic, asleep) may be read by another joint of the
   same colour on another worker at the same time. */
static GA2D__HOT void ga2d__jstore_moved(const ga2d__joint *j, ga2d__sbody *sa, ga2d__sbody *sb, ga2d__jbody A, ga2d__jbody B)
{
    if (j->ima != 0 || j->iia != 0) ga2d__jstore(sa, A);
    if (j->imb != 0 || j->iib != 0) ga2d__jstore(sb, B);
}

/* An anchor r (from the centre, where the step began) turned as its body
   has since: r dq. */
static GA2D__HOT ga2d_vec ga2d__jturn(const ga2d__sbody *s, ga2d_vec r) { return ga2d_rotate(ga2d__rotor(s->dqc, s->dqs), r); }

/* The impulse P at anchors ra, rb and the axial impulse L (a torque
   impulse on B, its opposite on A): v += P / m, w += (r ^ P + L) / I on
   B, the opposite on A (the paper's impulse response, eq. for the
   angular part: the bivector r ^ P over the inertia). */
static GA2D__HOT void ga2d__japply(const ga2d__joint *j, ga2d__jbody *A, ga2d__jbody *B, ga2d_vec ra, ga2d_vec rb, ga2d_vec P, ga2d_real L)
{
    A->v = ga2d_vec_sub(A->v, ga2d_vec_scale(P, j->ima));
    A->w -= j->iia * (ga2d_wedge(ra, P) + L);
    B->v = ga2d_vec_add(B->v, ga2d_vec_scale(P, j->imb));
    B->w += j->iib * (ga2d_wedge(rb, P) + L);
}

/* B's anchor less A's now: the centres' offset where the step began,
   their motion since, the turned anchors. */
static GA2D__HOT ga2d_vec ga2d__joint_span(const ga2d__sbody *sa, const ga2d__sbody *sb, const ga2d__joint *j, ga2d_vec ra, ga2d_vec rb)
{
    return ga2d_vec_add(ga2d_vec_add(ga2d_vec_make(sb->dpx - sa->dpx, sb->dpy - sa->dpy), ga2d_vec_sub(rb, ra)), j->delta_center);
}

/* The velocity of B's anchor relative to A's: vb + w_b rb_perp - va -
   w_a ra_perp (the bivector w e12 acting on r). */
static GA2D__HOT ga2d_vec ga2d__joint_cdot(const ga2d__jbody *A, const ga2d__jbody *B, ga2d_vec ra, ga2d_vec rb)
{
    return ga2d_vec_sub(ga2d_vec_add(B->v, ga2d_vec_scale(ga2d_vec_perp(rb), B->w)),
                        ga2d_vec_add(A->v, ga2d_vec_scale(ga2d_vec_perp(ra), A->w)));
}

/* Bare hinges in lanes.  A revolute joint with no spring, motor or limit
   (a bridge's, a chain's, a grid's, a ragdoll's hinge) is its point
   constraint alone; GA2D__LANES of one colour are solved at once, as the
   contacts' lanes are, each lane computing exactly what
   ga2d__solve_revolute and ga2d__warm_start_joints compute for its joint,
   operation for operation: the same bits.  They are packed once a step
   into a group (about a fifth of the four joints' own bytes, which every
   pass streamed: joint_grid's 19 794 joints are 5 MB) and their impulses
   stored back after the substeps.  A colour's bare hinges come first in
   its joints (its joints commute exactly, so their order there is no
   bit's), whole groups of them packed and the rest solved one by one. */
struct ga2d__jgroup {
    int a[GA2D__LANES], b[GA2D__LANES];
    int first;                   /* the first lane's place in joint_order */
    ga2d__wmask move_a, move_b;  /* all ones where the lane moves A, B */
    ga2d__w rax, ray, rbx, rby;  /* anchors from the centres where the step began */
    ga2d__w dcx, dcy;            /* B's centre less A's then */
    ga2d__w ima, imb, iia, iib;
    ga2d__w lix, liy;            /* the point's accumulated impulse */
    ga2d__w axial;               /* the axial impulses' sum: no pass of a bare hinge changes it */
};

/* A colour's joints run in blocks of GA2D__JOINT_BLOCK from its first:
   a whole number of groups, so no block splits one. */
typedef char ga2d__joint_block_holds_groups[GA2D__JOINT_BLOCK % GA2D__LANES == 0 ? 1 : -1];

/* Book-keeping, after the joints are coloured and sorted (each colour's
   bare hinges first, ga2d__sort_joints): a group for every GA2D__LANES of
   them.  Out of memory, none is packed: every joint is solved one by
   one, to the same bits, and the step reports it. */
static void ga2d__pack_hinges(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int k, i, m, groups = 0, g = 0;
    c->jgroup_count = 0;
    if (c->joint_active == 0) return;
    for (k = 0; k < c->colour_count; ++k) groups += c->joint_bare[k] / GA2D__LANES;
    if (groups == 0) return;
    if (!ga2d__grow(&w->mem, (void **)&c->jgroups, &c->jgroup_capacity, groups, sizeof *c->jgroups) ||
        !ga2d__grow(&w->mem, (void **)&c->joint_lane, &c->joint_lane_capacity, c->joint_active, sizeof *c->joint_lane)) {
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return;
    }
    memset(c->joint_lane, 0, (size_t)c->joint_active * sizeof *c->joint_lane);
    for (k = 0; k < c->colour_count; ++k)
        for (m = 0; m < c->joint_bare[k] / GA2D__LANES; ++m, ++g) {
            c->jgroups[g].first = c->joint_start[k] + m * GA2D__LANES;
            for (i = 0; i < GA2D__LANES; ++i) c->joint_lane[c->jgroups[g].first + i] = g * GA2D__LANES + i + 1;
        }
    c->jgroup_count = groups;
}

/* Stage, over the hinge groups: their joints' prepared data into lanes,
   and each joint its lane (ga2d__point_impulse, ga2d__hinge_forget). */
static void ga2d__fill_hinges(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int gi, l;
    for (gi = begin; gi < end; ++gi) {
        ga2d__jgroup *g = &c->jgroups[gi];
        for (l = 0; l < GA2D__LANES; ++l) {
            ga2d__joint *j = &w->joints[c->joint_order[g->first + l]];
            j->lane = gi * GA2D__LANES + l + 1;
            g->a[l] = j->body[0];
            g->b[l] = j->body[1];
            GA2D__LANE(g->move_a, l) = -(j->ima != 0 || j->iia != 0);
            GA2D__LANE(g->move_b, l) = -(j->imb != 0 || j->iib != 0);
            GA2D__LANE(g->rax, l) = j->ra.x;
            GA2D__LANE(g->ray, l) = j->ra.y;
            GA2D__LANE(g->rbx, l) = j->rb.x;
            GA2D__LANE(g->rby, l) = j->rb.y;
            GA2D__LANE(g->dcx, l) = j->delta_center.x;
            GA2D__LANE(g->dcy, l) = j->delta_center.y;
            GA2D__LANE(g->ima, l) = j->ima;
            GA2D__LANE(g->imb, l) = j->imb;
            GA2D__LANE(g->iia, l) = j->iia;
            GA2D__LANE(g->iib, l) = j->iib;
            GA2D__LANE(g->lix, l) = j->linear_impulse.x;
            GA2D__LANE(g->liy, l) = j->linear_impulse.y;
            GA2D__LANE(g->axial, l) = ga2d__joint_axial_impulse(j);
        }
    }
}

/* Stage, over the hinge groups, after the substeps: the impulses back to
   their joints, which leave the lanes. */
static void ga2d__store_hinges(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int gi, l;
    for (gi = begin; gi < end; ++gi) {
        const ga2d__jgroup *g = &c->jgroups[gi];
        for (l = 0; l < GA2D__LANES; ++l) {
            ga2d__joint *j = &w->joints[c->joint_order[g->first + l]];
            j->linear_impulse = ga2d_vec_make(GA2D__LANE(g->lix, l), GA2D__LANE(g->liy, l));
            j->lane = 0;
        }
    }
}

/* A packed hinge's point impulse as it is now (the lanes hold it during
   the substeps), or any joint's own. */
static ga2d_vec ga2d__point_impulse(const ga2d_world *w, const ga2d__joint *j)
{
    const ga2d__jgroup *g;
    int l;
    if (j->lane == 0 || w->step.jgroup_count == 0) return j->linear_impulse;
    g = &w->step.jgroups[(j->lane - 1) / GA2D__LANES];
    l = (j->lane - 1) % GA2D__LANES;
    return ga2d_vec_make(GA2D__LANE(g->lix, l), GA2D__LANE(g->liy, l));
}

/* Containment: a packed hinge's impulses forgotten in its lane too. */
static void ga2d__hinge_forget(ga2d_world *w, const ga2d__joint *j)
{
    ga2d__jgroup *g;
    int l;
    if (j->lane == 0 || w->step.jgroup_count == 0) return;
    g = &w->step.jgroups[(j->lane - 1) / GA2D__LANES];
    l = (j->lane - 1) % GA2D__LANES;
    GA2D__LANE(g->lix, l) = GA2D__LANE(g->liy, l) = GA2D__LANE(g->axial, l) = 0;
}

/* The lanes' anchors turned as their bodies have turned since the step
   began (ga2d__jturn): r dq. */
typedef struct ga2d__wlevers { ga2d__w ax, ay, bx, by; } ga2d__wlevers;

static GA2D__HOT ga2d__wlevers ga2d__hinge_levers(const ga2d__jgroup *g, const ga2d__wbody *A, const ga2d__wbody *B)
{
    ga2d__wlevers r;
    r.ax = ga2d__wsub(ga2d__wmul(A->qc, g->rax), ga2d__wmul(A->qs, g->ray));
    r.ay = ga2d__wadd(ga2d__wmul(A->qs, g->rax), ga2d__wmul(A->qc, g->ray));
    r.bx = ga2d__wsub(ga2d__wmul(B->qc, g->rbx), ga2d__wmul(B->qs, g->rby));
    r.by = ga2d__wadd(ga2d__wmul(B->qs, g->rbx), ga2d__wmul(B->qc, g->rby));
    return r;
}

/* ga2d__japply in lanes: the impulse P at the levers and the axial L. */
static GA2D__HOT void ga2d__hinge_apply(const ga2d__jgroup *g, ga2d__wbody *A, ga2d__wbody *B, const ga2d__wlevers *r,
                                        ga2d__w px, ga2d__w py, ga2d__w L)
{
    A->vx = ga2d__wsub(A->vx, ga2d__wmul(px, g->ima));
    A->vy = ga2d__wsub(A->vy, ga2d__wmul(py, g->ima));
    A->w = ga2d__wsub(A->w, ga2d__wmul(g->iia, ga2d__wadd(ga2d__wsub(ga2d__wmul(r->ax, py), ga2d__wmul(r->ay, px)), L)));
    B->vx = ga2d__wadd(B->vx, ga2d__wmul(px, g->imb));
    B->vy = ga2d__wadd(B->vy, ga2d__wmul(py, g->imb));
    B->w = ga2d__wadd(B->w, ga2d__wmul(g->iib, ga2d__wadd(ga2d__wsub(ga2d__wmul(r->bx, py), ga2d__wmul(r->by, px)), L)));
}

/* A hinge group's warm start: last step's impulses at the anchors now. */
static GA2D__HOT void ga2d__warm_hinges(ga2d__step_context *c, const ga2d__jgroup *g)
{
    ga2d__wbody A, B;
    ga2d__wlevers r;
    ga2d__wload(c->sbodies, g->a, &A, 1);
    ga2d__wload(c->sbodies, g->b, &B, 1);
    r = ga2d__hinge_levers(g, &A, &B);
    ga2d__hinge_apply(g, &A, &B, &r, g->lix, g->liy, g->axial);
    ga2d__wstore(c->sbodies, g->a, g->move_a, &A);
    ga2d__wstore(c->sbodies, g->b, g->move_b, &B);
}

/* A hinge group's pass (ga2d__solve_point in lanes): the 2x2 block K P =
   -(cdot + the soft feedback of the anchors' gap) in a bias pass, -cdot
   in a relax pass. */
static GA2D__HOT void ga2d__solve_hinges(ga2d__step_context *c, ga2d__jgroup *g, int bias)
{
    const ga2d__w zero = ga2d__wsplat(0), one = ga2d__wsplat(1);
    ga2d__wbody A, B;
    ga2d__wlevers r;
    ga2d__w rx, ry, ms = one, is = zero, k11, k12, k22, det, mass, sx, sy, px, py;
    ga2d__wload(c->sbodies, g->a, &A, 1);
    ga2d__wload(c->sbodies, g->b, &B, 1);
    r = ga2d__hinge_levers(g, &A, &B);
    /* cdot: B's anchor's velocity less A's (ga2d__joint_cdot) */
    rx = ga2d__wsub(ga2d__wadd(B.vx, ga2d__wmul(ga2d__wneg(r.by), B.w)), ga2d__wadd(A.vx, ga2d__wmul(ga2d__wneg(r.ay), A.w)));
    ry = ga2d__wsub(ga2d__wadd(B.vy, ga2d__wmul(r.bx, B.w)), ga2d__wadd(A.vy, ga2d__wmul(r.ax, A.w)));
    if (bias) { /* the gap between the anchors now (ga2d__joint_span), fed back softly */
        const ga2d__soft *soft = &c->joint_soft;
        ga2d__w rate = ga2d__wsplat(soft->bias_rate);
        sx = ga2d__wadd(ga2d__wadd(ga2d__wsub(B.dpx, A.dpx), ga2d__wsub(r.bx, r.ax)), g->dcx);
        sy = ga2d__wadd(ga2d__wadd(ga2d__wsub(B.dpy, A.dpy), ga2d__wsub(r.by, r.ay)), g->dcy);
        rx = ga2d__wadd(rx, ga2d__wmul(sx, rate));
        ry = ga2d__wadd(ry, ga2d__wmul(sy, rate));
        ms = ga2d__wsplat(soft->mass_scale);
        is = ga2d__wsplat(soft->impulse_scale);
    }
    /* K^-1 (rx, ry) (ga2d__point_solve) */
    k11 = ga2d__wadd(ga2d__wadd(ga2d__wadd(g->ima, g->imb), ga2d__wmul(ga2d__wmul(g->iia, r.ay), r.ay)),
                     ga2d__wmul(ga2d__wmul(g->iib, r.by), r.by));
    k12 = ga2d__wsub(ga2d__wmul(ga2d__wmul(ga2d__wneg(g->iia), r.ax), r.ay), ga2d__wmul(ga2d__wmul(g->iib, r.bx), r.by));
    k22 = ga2d__wadd(ga2d__wadd(ga2d__wadd(g->ima, g->imb), ga2d__wmul(ga2d__wmul(g->iia, r.ax), r.ax)),
                     ga2d__wmul(ga2d__wmul(g->iib, r.bx), r.bx));
    det = ga2d__wsub(ga2d__wmul(k11, k22), ga2d__wmul(k12, k12));
    {
        ga2d__wmask nonzero = ga2d__wne(det, zero);
        det = ga2d__wsel(nonzero, ga2d__wdiv(one, ga2d__wsel(nonzero, det, one)), det);
    }
    mass = ga2d__wneg(ms);
    px = ga2d__wsub(ga2d__wmul(ga2d__wmul(det, ga2d__wsub(ga2d__wmul(k22, rx), ga2d__wmul(k12, ry))), mass), ga2d__wmul(g->lix, is));
    py = ga2d__wsub(ga2d__wmul(ga2d__wmul(det, ga2d__wsub(ga2d__wmul(k11, ry), ga2d__wmul(k12, rx))), mass), ga2d__wmul(g->liy, is));
    g->lix = ga2d__wadd(g->lix, px);
    g->liy = ga2d__wadd(g->liy, py);
    ga2d__hinge_apply(g, &A, &B, &r, px, py, zero);
    ga2d__wstore(c->sbodies, g->a, g->move_a, &A);
    ga2d__wstore(c->sbodies, g->b, g->move_b, &B);
}

/* The packed group at place i of joint_order, if one begins there. */
static ga2d__jgroup *ga2d__hinges_at(ga2d__step_context *c, int i)
{
    int lane = c->jgroup_count > 0 ? c->joint_lane[i] - 1 : -1;
    if (lane < 0) return NULL;
    GA2D_ASSERT(lane % GA2D__LANES == 0);
    return &c->jgroups[lane / GA2D__LANES];
}


static void ga2d__slider_warm(const ga2d__sbody *sa, const ga2d__sbody *sb, const ga2d__joint *j, ga2d__jbody *A, ga2d__jbody *B);

/* Stage, over the step's joints: last step's impulses, at the anchors as
   they are now. */
static void ga2d__warm_start_joints(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int i;
    for (i = begin; i < end; ++i) {
        const ga2d__jgroup *g = ga2d__hinges_at(c, i);
        const ga2d__joint *j;
        ga2d__sbody *sa, *sb;
        ga2d__jbody A, B;
        ga2d_vec ra, rb;
        if (g) {
            ga2d__warm_hinges(c, g);
            i += GA2D__LANES - 1;
            continue;
        }
        j = &w->joints[c->joint_order[i]];
        sa = &c->sbodies[j->body[0]];
        sb = &c->sbodies[j->body[1]];
        A = ga2d__jload(sa);
        B = ga2d__jload(sb);
        ra = ga2d__jturn(sa, j->ra);
        rb = ga2d__jturn(sb, j->rb);
        if (j->type == GA2D_JOINT_PRISMATIC || j->type == GA2D_JOINT_WHEEL) ga2d__slider_warm(sa, sb, j, &A, &B);
        else if (j->type == GA2D_JOINT_DISTANCE) /* its impulses lie along its axis */
            ga2d__japply(j, &A, &B, ra, rb, ga2d_vec_scale(ga2d__axis_of(ga2d__joint_span(sa, sb, j, ra, rb)), ga2d__joint_axial_impulse(j)), 0);
        else ga2d__japply(j, &A, &B, ra, rb, j->linear_impulse, ga2d__joint_axial_impulse(j));
        ga2d__jstore_moved(j, sa, sb, A, B);
    }
}

/* B's angle less A's and the reference now: the step's start plus the
   turns since (2D rotors commute: dq_a~ dq_b is the relative turn). */
static ga2d_real ga2d__joint_angle(const ga2d__sbody *sa, const ga2d__sbody *sb, const ga2d__joint *j)
{
    return j->delta_angle + ga2d_rotor_angle(ga2d__relative_rotor(ga2d__rotor(sa->dqc, sa->dqs), ga2d__rotor(sb->dqc, sb->dqs)));
}

/* One side of a limit (along the angle or a distance joint's axis, with
   that direction's mass), as a contact: C >= 0 is the room left.  Apart, it closes no faster than C / h (speculative);
   past it, the soft bias pushes back (bias passes only).  The impulse is
   accumulated and kept >= 0.  Returns the change, a torque impulse on B
   in the limit's sense (sign: +1 lower, -1 upper). */
static ga2d_real ga2d__limit_impulse(const ga2d__step_context *c, ga2d_real mass, ga2d_real C, ga2d_real Cdot,
                                     ga2d_real *accumulated, int bias)
{
    ga2d_real b = 0, ms = 1, is = 0, lambda, total;
    if (C > 0) b = C * c->inv_h;
    else if (bias) {
        b = c->joint_soft.bias_rate * C;
        ms = c->joint_soft.mass_scale;
        is = c->joint_soft.impulse_scale;
    }
    lambda = -mass * ms * (Cdot + b) - is * *accumulated;
    total = *accumulated + lambda > 0 ? *accumulated + lambda : 0;
    lambda = total - *accumulated;
    *accumulated = total;
    return lambda;
}

/* K^-1 r for a point constraint's 2x2 mass matrix K at anchors ra, rb:
   K = (1/m_a + 1/m_b) 1 + (1/I_a) [ra_y^2, -ra_x ra_y; -ra_x ra_y, ra_x^2]
   + the same for B (the paper's impulse denominator, for any direction). */
static GA2D__HOT ga2d_vec ga2d__point_solve(const ga2d__joint *j, ga2d_vec ra, ga2d_vec rb, ga2d_vec r)
{
    ga2d_real k11 = j->ima + j->imb + j->iia * ra.y * ra.y + j->iib * rb.y * rb.y;
    ga2d_real k12 = -j->iia * ra.x * ra.y - j->iib * rb.x * rb.y;
    ga2d_real k22 = j->ima + j->imb + j->iia * ra.x * ra.x + j->iib * rb.x * rb.x;
    ga2d_real det = k11 * k22 - k12 * k12;
    if (det != 0) det = 1 / det;
    return ga2d_vec_make(det * (k22 * r.x - k12 * r.y), det * (k11 * r.y - k12 * r.x));
}

/* The point constraint, B's anchor onto A's: the velocity error, and with
   a softness the separation `sep` fed back through it (NULL: rigid, no
   feedback: the relax pass). */
static GA2D__HOT void ga2d__solve_point(const ga2d__step_context *c, ga2d__joint *j, ga2d__jbody *A, ga2d__jbody *B, ga2d_vec ra,
                              ga2d_vec rb, ga2d_vec sep, const ga2d__soft *soft)
{
    ga2d_vec rhs = ga2d__joint_cdot(A, B, ra, rb), P;
    ga2d_real ms = 1, is = 0;
    (void)c;
    if (soft) {
        rhs = ga2d_vec_add(rhs, ga2d_vec_scale(sep, soft->bias_rate));
        ms = soft->mass_scale;
        is = soft->impulse_scale;
    }
    P = ga2d_vec_sub(ga2d_vec_scale(ga2d__point_solve(j, ra, rb, rhs), -ms), ga2d_vec_scale(j->linear_impulse, is));
    j->linear_impulse = ga2d_vec_add(j->linear_impulse, P);
    ga2d__japply(j, A, B, ra, rb, P, 0);
}

/* A revolute joint's pass (Catto's soft step, as Box2D v3 solves it):
   the spring, the motor and the limits along the angle, then the point
   constraint, B's anchor onto A's, as a 2x2 block.  bias: the pass that
   pushes errors out (the soft pass); a relax pass keeps velocities only. */
static void ga2d__solve_revolute(ga2d__step_context *c, ga2d__joint *j, int bias)
{
    ga2d__sbody *sa = &c->sbodies[j->body[0]], *sb = &c->sbodies[j->body[1]];
    ga2d__jbody A = ga2d__jload(sa), B = ga2d__jload(sb);
    ga2d_vec ra = ga2d__jturn(sa, j->ra), rb = ga2d__jturn(sb, j->rb);
    int turns = j->axial_mass > 0;
    ga2d_real angle = 0;
    if (turns && (j->enable_spring || j->enable_limit))
        angle = ga2d__joint_angle(sa, sb, j);
    if (turns && j->enable_spring && j->hertz > 0) {
        ga2d_real lambda = -j->spring.mass_scale * j->axial_mass * (B.w - A.w + j->spring.bias_rate * angle) -
                           j->spring.impulse_scale * j->spring_impulse;
        j->spring_impulse += lambda;
        A.w -= j->iia * lambda;
        B.w += j->iib * lambda;
    }
    if (turns && j->enable_motor) {
        ga2d_real cap = j->max_motor * c->h, old = j->motor_impulse;
        ga2d_real total = old - j->axial_mass * (B.w - A.w - j->motor_speed);
        j->motor_impulse = total < -cap ? -cap : (total > cap ? cap : total);
        A.w -= j->iia * (j->motor_impulse - old);
        B.w += j->iib * (j->motor_impulse - old);
    }
    if (turns && j->enable_limit) {
        ga2d_real lambda = ga2d__limit_impulse(c, j->axial_mass, angle - j->lower, B.w - A.w, &j->lower_impulse, bias);
        A.w -= j->iia * lambda;
        B.w += j->iib * lambda;
        lambda = ga2d__limit_impulse(c, j->axial_mass, j->upper - angle, A.w - B.w, &j->upper_impulse, bias);
        A.w += j->iia * lambda;
        B.w -= j->iib * lambda;
    }
    ga2d__solve_point(c, j, &A, &B, ra, rb, bias ? ga2d__joint_span(sa, sb, j, ra, rb) : ga2d_vec_make(0, 0),
                      bias ? &c->joint_soft : NULL);
    ga2d__jstore_moved(j, sa, sb, A, B);
}

/* An impulse along a distance joint's axis (its direction's mass m):
   lambda = -ms m (cdot + bias) - is acc, accumulated, applied at the
   anchors. */
static ga2d_real ga2d__axis_impulse(const ga2d__joint *j, ga2d__jbody *A, ga2d__jbody *B, ga2d_vec ra, ga2d_vec rb, ga2d_vec axis,
                                    ga2d_real m, ga2d_real bias, const ga2d__soft *soft, ga2d_real *acc)
{
    ga2d_real cdot = ga2d_dot(axis, ga2d__joint_cdot(A, B, ra, rb)), ms = soft ? soft->mass_scale : 1;
    ga2d_real is = soft ? soft->impulse_scale : 0;
    ga2d_real lambda = -ms * m * (cdot + bias) - is * *acc;
    *acc += lambda;
    ga2d__japply(j, A, B, ra, rb, ga2d_vec_scale(axis, lambda), 0);
    return lambda;
}

/* A distance joint's pass: along the axis between the anchors as they
   are now, the rigid length (with the feedback in bias passes) or the
   spring, then the range's two sides and the motor. */
static void ga2d__solve_distance(ga2d__step_context *c, ga2d__joint *j, int bias)
{
    ga2d__sbody *sa = &c->sbodies[j->body[0]], *sb = &c->sbodies[j->body[1]];
    ga2d__jbody A = ga2d__jload(sa), B = ga2d__jload(sb);
    ga2d_vec ra = ga2d__jturn(sa, j->ra), rb = ga2d__jturn(sb, j->rb), d = ga2d__joint_span(sa, sb, j, ra, rb);
    ga2d_vec axis = ga2d__axis_of(d);
    ga2d_real len = ga2d_vec_length(d), wa = ga2d_wedge(ra, axis), wb = ga2d_wedge(rb, axis);
    ga2d_real k = j->ima + j->imb + j->iia * wa * wa + j->iib * wb * wb, m = k > 0 ? 1 / k : 0;
    int ranged = j->enable_limit && j->lower < j->upper;
    int pinned = j->enable_limit && !ranged; /* a range of no width: rigid at it, whatever the length or spring */
    ga2d_real target = pinned ? j->lower : j->length;
    if (j->enable_spring && j->hertz > 0 && !pinned) {
        if (!ranged || (len > j->lower && len < j->upper)) /* a rope's spring acts within its range */
            ga2d__axis_impulse(j, &A, &B, ra, rb, axis, m, j->spring.bias_rate * (len - j->length), &j->spring, &j->spring_impulse);
    } else if (!ranged) {
        ga2d__axis_impulse(j, &A, &B, ra, rb, axis, m, bias ? c->joint_soft.bias_rate * (len - target) : 0,
                           bias ? &c->joint_soft : NULL, &j->impulse);
    }
    if (ranged) {
        ga2d_real cdot = ga2d_dot(axis, ga2d__joint_cdot(&A, &B, ra, rb));
        ga2d_real lambda = ga2d__limit_impulse(c, m, len - j->lower, cdot, &j->lower_impulse, bias);
        ga2d__japply(j, &A, &B, ra, rb, ga2d_vec_scale(axis, lambda), 0);
        cdot = ga2d_dot(axis, ga2d__joint_cdot(&A, &B, ra, rb));
        lambda = ga2d__limit_impulse(c, m, j->upper - len, -cdot, &j->upper_impulse, bias);
        ga2d__japply(j, &A, &B, ra, rb, ga2d_vec_scale(axis, -lambda), 0);
    }
    if (j->enable_motor) {
        ga2d_real cap = j->max_motor * c->h, old = j->motor_impulse;
        ga2d_real total = old - m * (ga2d_dot(axis, ga2d__joint_cdot(&A, &B, ra, rb)) - j->motor_speed);
        j->motor_impulse = total < -cap ? -cap : (total > cap ? cap : total);
        ga2d__japply(j, &A, &B, ra, rb, ga2d_vec_scale(axis, j->motor_impulse - old), 0);
    }
    ga2d__jstore_moved(j, sa, sb, A, B);
}

/* A weld's pass: the angle, then the point, each rigid with the
   feedback in bias passes, or a spring of its own hertz in every pass
   (Box2D v3's weld). */
static void ga2d__solve_weld(ga2d__step_context *c, ga2d__joint *j, int bias)
{
    ga2d__sbody *sa = &c->sbodies[j->body[0]], *sb = &c->sbodies[j->body[1]];
    ga2d__jbody A = ga2d__jload(sa), B = ga2d__jload(sb);
    ga2d_vec ra = ga2d__jturn(sa, j->ra), rb = ga2d__jturn(sb, j->rb);
    const ga2d__soft *angular = j->hertz > 0 ? &j->spring : (bias ? &c->joint_soft : NULL);
    const ga2d__soft *linear = j->linear_hertz > 0 ? &j->linear_spring : (bias ? &c->joint_soft : NULL);
    if (j->axial_mass > 0) {
        ga2d_real b = angular ? angular->bias_rate * ga2d__joint_angle(sa, sb, j) : 0;
        ga2d_real ms = angular ? angular->mass_scale : 1, is = angular ? angular->impulse_scale : 0;
        ga2d_real lambda = -ms * j->axial_mass * (B.w - A.w + b) - is * j->impulse;
        j->impulse += lambda;
        A.w -= j->iia * lambda;
        B.w += j->iib * lambda;
    }
    ga2d__solve_point(c, j, &A, &B, ra, rb, linear ? ga2d__joint_span(sa, sb, j, ra, rb) : ga2d_vec_make(0, 0), linear);
    ga2d__jstore_moved(j, sa, sb, A, B);
}

/* A motor joint's pass: the velocity that closes `correction` of the
   angle's and the anchors' gaps this substep, within max_torque and
   max_force (accumulated impulses clamped: |P| <= F h), in every pass
   (it is a drive, not a constraint the relax pass should leave). */
static void ga2d__solve_motor(ga2d__step_context *c, ga2d__joint *j)
{
    ga2d__sbody *sa = &c->sbodies[j->body[0]], *sb = &c->sbodies[j->body[1]];
    ga2d__jbody A = ga2d__jload(sa), B = ga2d__jload(sb);
    ga2d_vec ra = ga2d__jturn(sa, j->ra), rb = ga2d__jturn(sb, j->rb), gap, rhs, old = j->linear_impulse, P;
    ga2d_real rate = j->correction * c->inv_h, cap;
    if (j->axial_mass > 0) {
        ga2d_real prev = j->impulse, total;
        cap = j->max_torque * c->h;
        total = prev - j->axial_mass * (B.w - A.w + rate * ga2d__joint_angle(sa, sb, j));
        j->impulse = total < -cap ? -cap : (total > cap ? cap : total);
        A.w -= j->iia * (j->impulse - prev);
        B.w += j->iib * (j->impulse - prev);
    }
    /* the gap: B's anchor less (A's anchor + the offset, turned with A) */
    gap = ga2d_vec_sub(ga2d__joint_span(sa, sb, j, ra, rb), ga2d__jturn(sa, j->target));
    rhs = ga2d_vec_add(ga2d__joint_cdot(&A, &B, ra, rb), ga2d_vec_scale(gap, rate));
    P = ga2d_vec_add(old, ga2d_vec_scale(ga2d__point_solve(j, ra, rb, rhs), -1));
    cap = j->max_force * c->h;
    if (ga2d_vec_length(P) > cap) P = ga2d_vec_scale(ga2d__axis_of(P), cap);
    j->linear_impulse = P;
    ga2d__japply(j, &A, &B, ra, rb, ga2d_vec_sub(P, old), 0);
    ga2d__jstore_moved(j, sa, sb, A, B);
}

/* A slider's frame now (prismatic, wheel): the anchors, B's anchor from
   A's (d), A's axis turned with A and its normal, and the levers: along
   the axis A pushes at the point of A under B's anchor (d + ra), B at
   rb, so a1 = (d + ra) ^ axis, a2 = rb ^ axis, and s1, s2 the same for
   the normal. */
typedef struct ga2d__slider {
    ga2d_vec ra, rb, d, axis, perp;
    ga2d_real a1, a2, s1, s2;
} ga2d__slider;

static ga2d__slider ga2d__slider_frame(const ga2d__sbody *sa, const ga2d__sbody *sb, const ga2d__joint *j)
{
    ga2d__slider f;
    ga2d_vec lever;
    f.ra = ga2d__jturn(sa, j->ra);
    f.rb = ga2d__jturn(sb, j->rb);
    f.d = ga2d__joint_span(sa, sb, j, f.ra, f.rb);
    f.axis = ga2d__jturn(sa, j->target);
    f.perp = ga2d_vec_perp(f.axis);
    lever = ga2d_vec_add(f.d, f.ra);
    f.a1 = ga2d_wedge(lever, f.axis);
    f.a2 = ga2d_wedge(f.rb, f.axis);
    f.s1 = ga2d_wedge(lever, f.perp);
    f.s2 = ga2d_wedge(f.rb, f.perp);
    return f;
}

/* A linear impulse P with the torque impulses la on A, lb on B: v -= P /
   m_a, w_a -= la / I_a; v_b += P / m_b, w_b += lb / I_b. */
static void ga2d__japply_levers(const ga2d__joint *j, ga2d__jbody *A, ga2d__jbody *B, ga2d_vec P, ga2d_real la, ga2d_real lb)
{
    A->v = ga2d_vec_sub(A->v, ga2d_vec_scale(P, j->ima));
    A->w -= j->iia * la;
    B->v = ga2d_vec_add(B->v, ga2d_vec_scale(P, j->imb));
    B->w += j->iib * lb;
}

/* The rate of a slider's translation along its axis (the velocity part
   the solver sees: the axis's turn is left to the feedback). */
static ga2d_real ga2d__slider_rate(const ga2d__slider *f, const ga2d__jbody *A, const ga2d__jbody *B)
{
    return ga2d_dot(f->axis, ga2d_vec_sub(B->v, A->v)) + f->a2 * B->w - f->a1 * A->w;
}

/* An impulse lambda along the axis. */
static void ga2d__slider_push(const ga2d__joint *j, const ga2d__slider *f, ga2d__jbody *A, ga2d__jbody *B, ga2d_real lambda)
{
    ga2d__japply_levers(j, A, B, ga2d_vec_scale(f->axis, lambda), lambda * f->a1, lambda * f->a2);
}

/* Along a slider's axis: its spring (pulling the translation to 0), its
   motor (prismatic: a force along the axis) and its limits. */
static void ga2d__slider_axis(ga2d__step_context *c, ga2d__joint *j, const ga2d__slider *f, ga2d__jbody *A, ga2d__jbody *B, int bias,
                              int linear_motor)
{
    ga2d_real k = j->ima + j->imb + j->iia * f->a1 * f->a1 + j->iib * f->a2 * f->a2, m = k > 0 ? 1 / k : 0;
    ga2d_real translation = ga2d_dot(f->axis, f->d), lambda;
    if (j->enable_spring && j->hertz > 0) {
        lambda = -j->spring.mass_scale * m * (ga2d__slider_rate(f, A, B) + j->spring.bias_rate * translation) -
                 j->spring.impulse_scale * j->spring_impulse;
        j->spring_impulse += lambda;
        ga2d__slider_push(j, f, A, B, lambda);
    }
    if (linear_motor && j->enable_motor) {
        ga2d_real cap = j->max_motor * c->h, old = j->motor_impulse, total = old - m * (ga2d__slider_rate(f, A, B) - j->motor_speed);
        j->motor_impulse = total < -cap ? -cap : (total > cap ? cap : total);
        ga2d__slider_push(j, f, A, B, j->motor_impulse - old);
    }
    if (j->enable_limit) {
        lambda = ga2d__limit_impulse(c, m, translation - j->lower, ga2d__slider_rate(f, A, B), &j->lower_impulse, bias);
        ga2d__slider_push(j, f, A, B, lambda);
        lambda = ga2d__limit_impulse(c, m, j->upper - translation, -ga2d__slider_rate(f, A, B), &j->upper_impulse, bias);
        ga2d__slider_push(j, f, A, B, -lambda);
    }
}

/* A prismatic joint's pass: along the axis, then the normal and the
   angle held together as a 2x2 block, K = [m_a + m_b + s1^2 / I_a + s2^2
   / I_b, s1 / I_a + s2 / I_b; same, 1 / I_a + 1 / I_b] (Box2D v3's). */
static void ga2d__solve_prismatic(ga2d__step_context *c, ga2d__joint *j, int bias)
{
    ga2d__sbody *sa = &c->sbodies[j->body[0]], *sb = &c->sbodies[j->body[1]];
    ga2d__jbody A = ga2d__jload(sa), B = ga2d__jload(sb);
    ga2d__slider f = ga2d__slider_frame(sa, sb, j);
    ga2d_real k11, k12, k22, det, r1, r2, ms = 1, is = 0;
    ga2d_vec imp;
    ga2d__slider_axis(c, j, &f, &A, &B, bias, 1);
    r1 = ga2d_dot(f.perp, ga2d_vec_sub(B.v, A.v)) + f.s2 * B.w - f.s1 * A.w;
    r2 = B.w - A.w;
    if (bias) {
        r1 += c->joint_soft.bias_rate * ga2d_dot(f.perp, f.d);
        r2 += c->joint_soft.bias_rate * ga2d__joint_angle(sa, sb, j);
        ms = c->joint_soft.mass_scale;
        is = c->joint_soft.impulse_scale;
    }
    k11 = j->ima + j->imb + j->iia * f.s1 * f.s1 + j->iib * f.s2 * f.s2;
    k12 = j->iia * f.s1 + j->iib * f.s2;
    k22 = j->iia + j->iib > 0 ? j->iia + j->iib : 1; /* neither turns: the angle's row is idle */
    det = k11 * k22 - k12 * k12;
    if (det != 0) det = 1 / det;
    imp = ga2d_vec_make(-ms * det * (k22 * r1 - k12 * r2) - is * j->linear_impulse.x,
                        -ms * det * (k11 * r2 - k12 * r1) - is * j->linear_impulse.y);
    j->linear_impulse = ga2d_vec_add(j->linear_impulse, imp);
    ga2d__japply_levers(j, &A, &B, ga2d_vec_scale(f.perp, imp.x), imp.x * f.s1 + imp.y, imp.x * f.s2 + imp.y);
    ga2d__jstore_moved(j, sa, sb, A, B);
}

/* A wheel joint's pass: the motor on the relative spin, the suspension
   and limits along the axis, then B's anchor held on A's line (the
   normal only). */
static void ga2d__solve_wheel(ga2d__step_context *c, ga2d__joint *j, int bias)
{
    ga2d__sbody *sa = &c->sbodies[j->body[0]], *sb = &c->sbodies[j->body[1]];
    ga2d__jbody A = ga2d__jload(sa), B = ga2d__jload(sb);
    ga2d__slider f = ga2d__slider_frame(sa, sb, j);
    ga2d_real k, m, lambda, b = 0, ms = 1, is = 0;
    if (j->enable_motor && j->axial_mass > 0) {
        ga2d_real cap = j->max_motor * c->h, old = j->motor_impulse, total = old - j->axial_mass * (B.w - A.w - j->motor_speed);
        j->motor_impulse = total < -cap ? -cap : (total > cap ? cap : total);
        A.w -= j->iia * (j->motor_impulse - old);
        B.w += j->iib * (j->motor_impulse - old);
    }
    ga2d__slider_axis(c, j, &f, &A, &B, bias, 0);
    if (bias) {
        b = c->joint_soft.bias_rate * ga2d_dot(f.perp, f.d);
        ms = c->joint_soft.mass_scale;
        is = c->joint_soft.impulse_scale;
    }
    k = j->ima + j->imb + j->iia * f.s1 * f.s1 + j->iib * f.s2 * f.s2;
    m = k > 0 ? 1 / k : 0;
    lambda = -ms * m * (ga2d_dot(f.perp, ga2d_vec_sub(B.v, A.v)) + f.s2 * B.w - f.s1 * A.w + b) - is * j->impulse;
    j->impulse += lambda;
    ga2d__japply_levers(j, &A, &B, ga2d_vec_scale(f.perp, lambda), lambda * f.s1, lambda * f.s2);
    ga2d__jstore_moved(j, sa, sb, A, B);
}

/* A slider's warm start: the axial impulses along the axis, the normal's
   along the normal, the angular ones (prismatic: the angle's; wheel: the
   motor's) as torques. */
static void ga2d__slider_warm(const ga2d__sbody *sa, const ga2d__sbody *sb, const ga2d__joint *j, ga2d__jbody *A, ga2d__jbody *B)
{
    ga2d__slider f = ga2d__slider_frame(sa, sb, j);
    int prismatic = j->type == GA2D_JOINT_PRISMATIC;
    ga2d_real axial = j->spring_impulse + j->lower_impulse - j->upper_impulse + (prismatic ? j->motor_impulse : 0);
    ga2d_real normal = prismatic ? j->linear_impulse.x : j->impulse, turn = prismatic ? j->linear_impulse.y : j->motor_impulse;
    ga2d_vec P = ga2d_vec_add(ga2d_vec_scale(f.axis, axial), ga2d_vec_scale(f.perp, normal));
    ga2d__japply_levers(j, A, B, P, axial * f.a1 + normal * f.s1 + turn, axial * f.a2 + normal * f.s2 + turn);
}

/* Stage, over the step's joints: a pass, with the bias or without. */
static void ga2d__solve_joints(ga2d__step_context *c, int begin, int end, int bias)
{
    ga2d_world *w = c->world;
    int i;
    for (i = begin; i < end; ++i) {
        ga2d__jgroup *g = ga2d__hinges_at(c, i);
        ga2d__joint *j;
        if (g) {
            ga2d__solve_hinges(c, g, bias);
            i += GA2D__LANES - 1;
            continue;
        }
        j = &w->joints[c->joint_order[i]];
        switch (j->type) {
        case GA2D_JOINT_REVOLUTE: ga2d__solve_revolute(c, j, bias); break;
        case GA2D_JOINT_DISTANCE: ga2d__solve_distance(c, j, bias); break;
        case GA2D_JOINT_WELD: ga2d__solve_weld(c, j, bias); break;
        case GA2D_JOINT_PRISMATIC: ga2d__solve_prismatic(c, j, bias); break;
        case GA2D_JOINT_WHEEL: ga2d__solve_wheel(c, j, bias); break;
        default: ga2d__solve_motor(c, j); break;
        }
    }
}

/* Containment: a blown-up body's joints forget their impulses (else
   warm starting hands the NaN back to it and on to its neighbours). */
static void ga2d__joints_forget(ga2d_world *w, int slot)
{
    int link;
    for (link = ga2d__first_joint(w, slot); link >= 0; link = ga2d__next_joint(w, link)) {
        ga2d__joint_forget(&w->joints[link >> 1]);
        ga2d__hinge_forget(w, &w->joints[link >> 1]);
    }
}

/* ============================================================ world step */
/* RK4's per-body scratch for one substep: the start state, the derivative
   of the last stage and the weighted sum of the stages. */
struct ga2d__rk4 {
    ga2d_vec x0, v0, kx, kv, sx, sv;
    ga2d_rotor q0;
    ga2d_real w0, kth, kw, sth, sw;
};

/* ------------------------------------------------- the context's memory */
/* RK4's scratch for n moving bodies: kept at the moving list's capacity,
   so that a step never allocates it. */
static int ga2d__reserve_rk4(ga2d_world *w, int n)
{
    return ga2d__grow(&w->mem, (void **)&w->step.rk4, &w->step.rk4_capacity, n, sizeof *w->step.rk4);
}

/* A refit bit, a fast bit and a kbody for each of n moving bodies: kept at the
   moving list's capacity, so that a step never allocates them. */
static int ga2d__reserve_moving(ga2d_world *w, int n)
{
    ga2d__step_context *c = &w->step;
    return ga2d__grow(&w->mem, (void **)&c->refits, &c->refit_capacity, (n + 63) / 64, sizeof *c->refits) &&
           ga2d__grow(&w->mem, (void **)&c->fast, &c->fast_capacity, (n + 63) / 64, sizeof *c->fast) &&
           ga2d__grow(&w->mem, (void **)&c->kbodies, &c->kbody_capacity, n, sizeof *c->kbodies);
}

/* A solver body for each of n body slots and the dummy past them: kept at
   the slots' count, so that a step never allocates them
   (ga2d__compact_begin, ga2d__reserve_sbodies; ga2d_world_compact gives
   them back, and the next step takes them again). */
static int ga2d__reserve_slots(ga2d_world *w, int n)
{
    return ga2d__grow(&w->mem, (void **)&w->step.sbodies, &w->step.sbody_capacity, n + 1, sizeof *w->step.sbodies);
}

/* The solver's arrays given back (ga2d_world_compact); the next step
   allocates what it needs. */
static void ga2d__step_release(ga2d_world *w)
{
    ga2d__step_context *c = &w->step;
    ga2d__release(w, (void **)&c->order, &c->order_capacity, sizeof *c->order);
    ga2d__release(w, (void **)&c->constraints, &c->constraint_capacity, sizeof *c->constraints);
    c->constraint_count = 0;
    ga2d__release(w, (void **)&c->groups, &c->group_capacity, sizeof *c->groups);
    ga2d__release(w, (void **)&c->fill, &c->fill_capacity, sizeof *c->fill);
    c->group_count = c->colour_count = 0;
    ga2d__release(w, (void **)&c->group_extras, &c->group_extra_capacity, sizeof *c->group_extras);
    ga2d__release(w, (void **)&c->sbodies, &c->sbody_capacity, sizeof *c->sbodies);
    ga2d__release(w, (void **)&c->last_group, &c->last_group_capacity, sizeof *c->last_group);
    ga2d__release(w, (void **)&c->colour_masks, &c->colour_mask_capacity, sizeof *c->colour_masks);
    ga2d__release(w, (void **)&c->lane_constraints, &c->lane_constraint_capacity, sizeof *c->lane_constraints);
    ga2d__release(w, (void **)&c->lane_keys, &c->lane_key_capacity, sizeof *c->lane_keys);
    ga2d__release(w, (void **)&c->still_slots, &c->still_capacity, sizeof *c->still_slots);
    c->lane_key_count = -1; /* its groups are gone */
    ga2d__release(w, (void **)&c->joint_sorted, &c->joint_sorted_capacity, sizeof *c->joint_sorted);
    ga2d__release(w, (void **)&c->joint_perm, &c->joint_perm_capacity, sizeof *c->joint_perm);
    ga2d__release(w, (void **)&c->jgroups, &c->jgroup_capacity, sizeof *c->jgroups);
    ga2d__release(w, (void **)&c->joint_lane, &c->joint_lane_capacity, sizeof *c->joint_lane);
    c->jgroup_count = 0;
    ga2d__release(w, (void **)&c->joint_colours, &c->joint_colour_capacity, sizeof *c->joint_colours);
    ga2d__release(w, (void **)&c->kicked, &c->kicked_capacity, sizeof *c->kicked);
    ga2d__release(w, (void **)&c->changed, &c->changed_capacity, sizeof *c->changed);
    ga2d__release(w, (void **)&c->tally, &c->tally_capacity, sizeof *c->tally);
    ga2d__release(w, (void **)&c->counts, &c->counts_capacity, sizeof *c->counts);
    ga2d__release(w, (void **)&c->team_lines, &c->team_line_capacity, sizeof *c->team_lines);
}

/* Everything the context holds, freed with its world. */
static void ga2d__step_free(const ga2d_allocator *a, ga2d__step_context *c)
{
    GA2D__FREE_ARRAY(a, c->rk4, c->rk4_capacity);
    GA2D__FREE_ARRAY(a, c->order, c->order_capacity);
    GA2D__FREE_ARRAY(a, c->touch_seen, c->touch_seen_capacity);
    GA2D__FREE_ARRAY(a, c->constraints, c->constraint_capacity);
    GA2D__FREE_ARRAY(a, c->groups, c->group_capacity);
    GA2D__FREE_ARRAY(a, c->fill, c->fill_capacity);
    GA2D__FREE_ARRAY(a, c->group_extras, c->group_extra_capacity);
    GA2D__FREE_ARRAY(a, c->sbodies, c->sbody_capacity);
    GA2D__FREE_ARRAY(a, c->kbodies, c->kbody_capacity);
    GA2D__FREE_ARRAY(a, c->last_group, c->last_group_capacity);
    GA2D__FREE_ARRAY(a, c->colour_masks, c->colour_mask_capacity);
    GA2D__FREE_ARRAY(a, c->lane_constraints, c->lane_constraint_capacity);
    GA2D__FREE_ARRAY(a, c->lane_keys, c->lane_key_capacity);
    GA2D__FREE_ARRAY(a, c->still_slots, c->still_capacity);
    GA2D__FREE_ARRAY(a, c->changed, c->changed_capacity);
    GA2D__FREE_ARRAY(a, c->refits, c->refit_capacity);
    GA2D__FREE_ARRAY(a, c->fast, c->fast_capacity);
    GA2D__FREE_ARRAY(a, c->tally, c->tally_capacity);
    GA2D__FREE_ARRAY(a, c->counts, c->counts_capacity);
    GA2D__FREE_ARRAY(a, c->team_lines, c->team_line_capacity);
    GA2D__FREE_ARRAY(a, c->joint_order, c->joint_order_capacity);
    GA2D__FREE_ARRAY(a, c->joint_keys, c->joint_key_capacity);
    GA2D__FREE_ARRAY(a, c->joint_seen, c->joint_seen_capacity);
    GA2D__FREE_ARRAY(a, c->joint_sorted, c->joint_sorted_capacity);
    GA2D__FREE_ARRAY(a, c->joint_perm, c->joint_perm_capacity);
    GA2D__FREE_ARRAY(a, c->jgroups, c->jgroup_capacity);
    GA2D__FREE_ARRAY(a, c->joint_lane, c->joint_lane_capacity);
    GA2D__FREE_ARRAY(a, c->joint_colours, c->joint_colour_capacity);
    GA2D__FREE_ARRAY(a, c->kicked, c->kicked_capacity);
}

/* Runs the force callback at time t on the bodies' current state.  The
   field never reads a state that is not finite: a body driven there
   since the last containment (a restitution above 1, an RK4 stage, a
   solver pass) is contained first. */
static void ga2d__eval_field(ga2d_world *w, double t)
{
    int k;
    if (!w->def.force_callback || w->destroy_pending) return; /* destroyed from it: no more calls */
    for (k = 0; k < w->moving_count; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        b->sim.field_force = ga2d_vec_make(0, 0);
        b->sim.field_torque = 0;
        if (!ga2d__state_finite(&b->sim)) ga2d__contain(w, w->moving[k]);
    }
    w->lock |= GA2D__LOCK_FIELD;
    w->eval_time = t;
    w->def.force_callback(w, w->def.force_context);
    w->lock &= ~GA2D__LOCK_FIELD;
    ++w->counters.force_evaluations;
}

/* a = g s + (F_user + F_field)/m and alpha = (tau_user + tau_field)/I */
static GA2D__HOT void ga2d__acceleration(const ga2d_world *w, const ga2d__body_sim *b, ga2d_vec *a, ga2d_real *alpha)
{
    ga2d_vec f = ga2d_vec_add(b->force, b->field_force);
    *a = ga2d_vec_add(ga2d_vec_scale(w->def.gravity, b->gravity_scale), ga2d_vec_scale(f, b->inv_mass));
    *alpha = (b->torque + b->field_torque) * b->inv_inertia;
}

/* Damping as the implicit factor 1/(1 + c h): stable for any c h. */
static GA2D__HOT void ga2d__damp(ga2d__body_sim *b, ga2d_real h)
{
    if (b->linear_damping > 0) b->v = ga2d_vec_scale(b->v, 1 / (1 + h * b->linear_damping));
    if (b->angular_damping > 0) b->w *= 1 / (1 + h * b->angular_damping);
}

/* Position update x += h v, q <- q exp(w h e12).  A body that does not
   turn (fixed rotation, or w = 0) skips the rotor altogether.  The
   step's motion is summed apart (dp, from the step's start) and x is
   x0 + dp: x rounds to the ulp of its coordinate, once a step instead of
   once a substep, and the solver reads dp itself (ga2d__gather).  Summed
   into x, each substep's move rounded to that ulp: far out a rolling disc
   was off by u / (2 v h) of its motion (5 % at 1e4 m in float, standing
   still past 1.3e5 m at 2 m/s), and in a resting pile the contacts saw
   the bodies move in steps of u (2-5e-7 m within 8 m of the origin),
   which the soft springs turned into a floor of 5e-5 m/s, a drift of
   0.5 mm in 10 s and kicks that never settled. */
static GA2D__HOT void ga2d__drift(const ga2d_world *w, ga2d__body_sim *b, ga2d_real h, ga2d__counts *n)
{
    b->dp = ga2d_vec_add(b->dp, ga2d_vec_scale(b->v, h));
    b->center = ga2d_vec_add(b->center0, b->dp);
    if (b->w != 0) {
        b->q = ga2d__turn(b->q, b->w * h, w->def.rotation_update);
        ++n->rotation_updates;
    }
    ++n->integrated_bodies;
}

/* ----------------------------------------------- velocities and positions */
/* Each integrator is split into a velocity phase and a position phase, so
   that the contact solver can act on the velocities in between:
   symplectic Euler kicks by h then drifts; Verlet kicks by h/2, drifts,
   evaluates the field and kicks by h/2 again; RK4 runs its four stages for
   the free motion, and the position phase adds to RK4's displacement what
   the contacts changed in the velocity (h dv). */

/* Containment: a body whose state is no longer finite (an absurd force,
   impulse or field drove it there) is put back where the step began, at
   rest and without forces, before anything it touches can see it; the
   step reports GA2D_ERR_NOT_FINITE and ga2d_world_error_body names the
   lowest slot of them (not the first met: the moving list's order is not
   a snapshot's).  Its neighbours stay finite. */
static void ga2d__contain(ga2d_world *w, int slot)
{
    ga2d__body *b = &w->bodies[slot];
    w->step.masses_stale = 1; /* it is back where the step began */
    b->sim.center = b->sim.center0;
    b->sim.dp = ga2d_vec_make(0, 0);
    b->sim.q = b->sim.q0;
    b->sim.dq = ga2d_rotor_identity(); /* a snapshot refuses a NaN here too */
    b->sim.v = ga2d_vec_make(0, 0);
    b->sim.w = 0;
    b->sim.force = ga2d_vec_make(0, 0);
    b->sim.torque = 0;
    /* the field's cache may hold what drove it (a snapshot refuses it) */
    b->sim.field_force = b->sim.field_accel = ga2d_vec_make(0, 0);
    b->sim.field_torque = b->sim.field_alpha = 0;
    b->sim.field_valid = 0;
    b->sleep_time = 0;
    {
        /* its contacts' accumulated impulses may hold what drove it: they
           restart from zero, or warm starting and the passes that follow
           would hand the NaN back to it and on to its neighbours */
        int i, k;
        for (i = 0; i < w->step.constraint_count; ++i) {
            ga2d__contact_constraint *c = &w->step.constraints[i];
            if (c->a != slot && c->b != slot) continue;
            for (k = 0; k < c->count; ++k) {
                ga2d_manifold_point *mp = &w->contacts[c->contact].manifold.points[k];
                c->p[k].normal_impulse = c->p[k].tangent_impulse = 0;
                mp->normal_impulse = mp->tangent_impulse = 0;
            }
            if (w->step.group_count > 0) ga2d__lane_clear(&w->step, c->lane);
        }
    }
    if (w->joint_count > 0) ga2d__joints_forget(w, slot);
    if (w->step.error == GA2D_OK) w->step.error = GA2D_ERR_NOT_FINITE;
    if (w->error_slot < 0 || slot < w->error_slot) w->error_slot = slot;
}

/* Shortens *v to length max if longer (returns 1 then); the length is
   taken after scaling by the larger component, so a huge but finite v is
   capped, not turned into inf or NaN. */
static GA2D__HOT int ga2d__cap_length(ga2d_vec *v, ga2d_real max)
{
    ga2d_real ax = GA2D__FABS(v->x), ay = GA2D__FABS(v->y), m = ax > ay ? ax : ay;
    if (m > max * GA2D__R(0.7)) { /* |v| may exceed max: measure it safely */
        ga2d_vec u = ga2d_vec_scale(*v, 1 / m);
        ga2d_real len = m * GA2D__SQRT(ga2d_dot(u, u));
        if (len > max) {
            *v = ga2d_vec_scale(u, m * (max / len));
            return 1;
        }
    }
    return 0;
}

static GA2D__HOT int ga2d__cap_turn(ga2d_real *th, ga2d_real max)
{
    if (!(*th > max || *th < -max)) return 0;
    *th = *th > 0 ? max : -max;
    return 1;
}

/* The velocity cap and the largest turn per substep, as Box2D: beyond
   them a body is tunnelling anyway; each capped body counts in
   speed_caps.  Returns 0 for a velocity that is not finite. */
static GA2D__HOT int ga2d__clamp_vw(const ga2d_world *w, ga2d_vec *v, ga2d_real *om, ga2d_real h, int *caps)
{
    if (!ga2d__finite_vec(*v) || !ga2d__finite(*om)) return 0;
    *caps += ga2d__cap_length(v, GA2D__MAX_SPEED * w->def.length_units_per_meter);
    *caps += ga2d__cap_turn(om, GA2D__MAX_TURN / h);
    return 1;
}
static GA2D__HOT int ga2d__clamp_velocity(const ga2d_world *w, ga2d__body_sim *b, ga2d_real h, int *caps)
{
    return ga2d__clamp_vw(w, &b->v, &b->w, h, caps);
}

/* A dynamic body's velocities capped, or the body contained when they are
   not finite. */
static void ga2d__cap_body(ga2d__step_context *c, ga2d__body *b, int slot)
{
    if (b->type == GA2D_BODY_DYNAMIC && !ga2d__clamp_velocity(c->world, &b->sim, c->h, &c->world->counters.speed_caps))
        ga2d__contain(c->world, slot);
}


/* Moving body k's kbody and solver body, from its record: at the step's
   first kick, and again for a body contained since. */
static GA2D__HOT void ga2d__kload(ga2d__step_context *c, int k)
{
    const ga2d_world *w = c->world;
    int slot = w->moving[k];
    const ga2d__body_sim *b = &w->bodies[slot].sim;
    ga2d__kbody *r = &c->kbodies[k];
    ga2d__sbody *s = &c->sbodies[slot];
    ga2d_real h = c->h, alpha;
    ga2d_vec a;
    ga2d_rotor dq = ga2d_rotor_mul(b->q, ga2d_rotor_inverse(b->q0)); /* as ga2d__gather */
    ga2d__acceleration(w, b, &a, &alpha);
    r->q = b->q;
    r->q0 = b->q0;
    r->dv = ga2d_vec_scale(a, h);
    r->dw = alpha * h;
    r->lin = b->linear_damping > 0 ? 1 / (1 + h * b->linear_damping) : 1; /* x 1 keeps every bit */
    r->ang = b->angular_damping > 0 ? 1 / (1 + h * b->angular_damping) : 1;
    r->dynamic = w->bodies[slot].type == GA2D_BODY_DYNAMIC;
    s->vx = b->v.x;
    s->vy = b->v.y;
    s->w = b->w;
    s->pad = 0;
    s->dpx = b->dp.x;
    s->dpy = b->dp.y;
    s->dqc = dq.c;
    s->dqs = dq.s;
}

/* Whether moving body k is dynamic with a velocity not finite (where the
   step keeps it now: ga2d__compact_begin). */
static int ga2d__unfinite_velocity(const ga2d__step_context *c, int k)
{
    int slot = c->world->moving[k];
    const ga2d__body *b = &c->world->bodies[slot];
    if (b->type != GA2D_BODY_DYNAMIC) return 0;
    if (c->compact) {
        const ga2d__sbody *s = &c->sbodies[slot];
        return !ga2d__finite(s->vx) || !ga2d__finite(s->vy) || !ga2d__finite(s->w);
    }
    return !ga2d__finite_vec(b->sim.v) || !ga2d__finite(b->sim.w);
}

/* Runs a counting stage over the n moving bodies, on the workers when it
   is long enough (and memory allows; out of memory is reported), then
   contains the bodies it left not finite (as `unfinite` tells them);
   returns how many it contained. */
typedef int ga2d__unfinite_fn(const ga2d__step_context *c, int k);
static int ga2d__run_checked(ga2d__step_context *c, ga2d__range_fn *fn, int n, ga2d__unfinite_fn *unfinite)
{
    ga2d_world *w = c->world;
    int blocks = (n + GA2D__SPLIT_BLOCK - 1) / GA2D__SPLIT_BLOCK, k, contained;
    int split = n >= GA2D__SPLIT_MIN && w->def.worker_count > 1 && w->def.enqueue_task;
    c->unfinite = 0;
    if (split && !ga2d__grow(&w->mem, (void **)&c->counts, &c->counts_capacity, blocks, sizeof *c->counts)) {
        c->error = GA2D_ERR_OUT_OF_MEMORY; /* reported; the stage runs here, to the same bits */
        split = 0;
    }
    if (split) {
        memset(c->counts, 0, (size_t)blocks * sizeof *c->counts);
        c->counts_split = 1;
        ga2d__run_blocks(c, fn, 0, n, GA2D__SPLIT_BLOCK);
        c->counts_split = 0;
        for (k = 0; k < blocks; ++k) ga2d__counts_add(c, &c->counts[k]);
    } else {
        ga2d__run(c, fn, n);
    }
    contained = c->unfinite;
    for (k = 0; k < n && c->unfinite > 0; ++k) {
        if (!unfinite(c, k)) continue;
        ga2d__contain(w, w->moving[k]);
        if (c->compact) ga2d__kload(c, k); /* as contained */
        --c->unfinite;
    }
    return contained;
}
/* The stages that leave a body with a velocity not finite. */
static int ga2d__run_counted(ga2d__step_context *c, ga2d__range_fn *fn, int n)
{
    return ga2d__run_checked(c, fn, n, ga2d__unfinite_velocity);
}

/* Stage, over the moving bodies: caches the field's acceleration (Verlet). */
static void ga2d__cache_field(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        b->sim.field_accel = ga2d_vec_scale(b->sim.field_force, b->sim.inv_mass);
        b->sim.field_alpha = b->sim.field_torque * b->sim.inv_inertia;
        b->sim.field_valid = 1;
    }
}

/* Half a kick with the cached field plus gravity and the user's forces. */
static void ga2d__verlet_kick(ga2d_world *w, ga2d__body_sim *b, ga2d_real half)
{
    ga2d_vec a = ga2d_vec_add(ga2d_vec_scale(w->def.gravity, b->gravity_scale),
                              ga2d_vec_add(b->field_accel, ga2d_vec_scale(b->force, b->inv_mass)));
    b->v = ga2d_vec_add(b->v, ga2d_vec_scale(a, half));
    b->w += (b->field_alpha + b->torque * b->inv_inertia) * half;
}

/* Classic RK4 on (x, theta, v, w), theta the turn since the substep began
   (rotations in the plane commute, so q = q0 exp(theta e12)); damping is
   the continuous -c v.  The velocity phase leaves every body at its start
   state with its free end velocity; the displacement waits in the
   scratch.  Without a force callback no stage writes a trial state and
   nothing is evaluated.  These four stages run over the moving bodies. */
static void ga2d__rk4_begin(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__rk4 *s = c->rk4;
    int k;
    for (k = begin; k < end; ++k) {
        const ga2d__body *b = &w->bodies[w->moving[k]];
        memset(&s[k], 0, sizeof s[k]);
        s[k].x0 = b->sim.center;
        s[k].q0 = b->sim.q;
        s[k].v0 = b->sim.v;
        s[k].w0 = b->sim.w;
    }
}

/* The trial state of the stage at rk4_at h, for the field to read. */
static void ga2d__rk4_trial(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__rk4 *s = c->rk4;
    ga2d_real at = c->rk4_at * c->h;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        b->sim.center = ga2d_vec_add(s[k].x0, ga2d_vec_scale(s[k].kx, at));
        b->sim.v = ga2d_vec_add(s[k].v0, ga2d_vec_scale(s[k].kv, at));
        b->sim.w = s[k].w0 + s[k].kw * at;
        b->sim.q = s[k].kth * at != 0 ? ga2d__turn(s[k].q0, s[k].kth * at, w->def.rotation_update) : s[k].q0;
    }
}

/* The stage's derivative, added to the weighted sum. */
static void ga2d__rk4_derive(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__rk4 *s = c->rk4;
    ga2d_real at = c->rk4_at * c->h, weight = c->rk4_weight;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        ga2d_vec v = ga2d_vec_add(s[k].v0, ga2d_vec_scale(s[k].kv, at));
        ga2d_real om = s[k].w0 + s[k].kw * at;
        s[k].kx = v;
        s[k].kth = om;
        if (b->type == GA2D_BODY_DYNAMIC) {
            ga2d_vec a;
            ga2d_real alpha;
            ga2d__acceleration(w, &b->sim, &a, &alpha);
            s[k].kv = ga2d_vec_sub(a, ga2d_vec_scale(v, b->sim.linear_damping));
            s[k].kw = alpha - b->sim.angular_damping * om;
        }
        s[k].sx = ga2d_vec_add(s[k].sx, ga2d_vec_scale(s[k].kx, weight));
        s[k].sv = ga2d_vec_add(s[k].sv, ga2d_vec_scale(s[k].kv, weight));
        s[k].sth += s[k].kth * weight;
        s[k].sw += s[k].kw * weight;
    }
}

/* The free end velocities, capped, from the start state. */
static void ga2d__rk4_end(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__rk4 *s = c->rk4;
    ga2d_real h = c->h;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        b->sim.center = s[k].x0;
        b->sim.q = s[k].q0;
        b->sim.v = ga2d_vec_add(s[k].v0, ga2d_vec_scale(s[k].sv, h / 6));
        b->sim.w = s[k].w0 + s[k].sw * (h / 6);
        s[k].kv = b->sim.v; /* the free end velocities, for the position phase */
        s[k].kw = b->sim.w;
        ga2d__cap_body(c, b, w->moving[k]);
    }
}

/* Stage, over the moving bodies: symplectic Euler's kick v += h a,
   w += h alpha, then damping and the caps. */
static void ga2d__kick(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__body *bodies = w->bodies; /* in locals: see ga2d__gather */
    const int *moving = w->moving;
    ga2d_real h = c->h;
    ga2d__counts n = {0, 0, 0, 0, 0};
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &bodies[moving[k]];
        ga2d_vec a;
        ga2d_real alpha;
        if (b->type != GA2D_BODY_DYNAMIC) continue;
        ga2d__acceleration(w, &b->sim, &a, &alpha);
        b->sim.v = ga2d_vec_add(b->sim.v, ga2d_vec_scale(a, h));
        b->sim.w += alpha * h;
        ga2d__damp(&b->sim, h);
        n.unfinite += !ga2d__clamp_velocity(w, &b->sim, h, &n.speed_caps); /* contained after the stage */
    }
    ga2d__counts_put(c, begin, &n);
}

/* Stage, over the moving bodies: ga2d__kick on the solver bodies
   (ga2d__compact_begin), the same operations in the same order. */
static void ga2d__ckick(ga2d__step_context *c, int begin, int end)
{
    const ga2d_world *w = c->world;
    const int *moving = w->moving; /* in locals: see ga2d__gather */
    const ga2d__kbody *kb = c->kbodies;
    ga2d__sbody *sb = c->sbodies;
    ga2d_real h = c->h;
    ga2d__counts n = {0, 0, 0, 0, 0};
    int k;
    for (k = begin; k < end; ++k) {
        const ga2d__kbody *r = &kb[k];
        ga2d__sbody *s = &sb[moving[k]];
        ga2d_vec v;
        ga2d_real om;
        if (!r->dynamic) continue;
        v = ga2d_vec_scale(ga2d_vec_make(s->vx + r->dv.x, s->vy + r->dv.y), r->lin);
        om = (s->w + r->dw) * r->ang;
        n.unfinite += !ga2d__clamp_vw(w, &v, &om, h, &n.speed_caps); /* contained after the stage */
        s->vx = v.x;
        s->vy = v.y;
        s->w = om;
    }
    ga2d__counts_put(c, begin, &n);
}

/* Stage, over the moving bodies: a Verlet half kick, capped. */
static void ga2d__half_kicks(ga2d__step_context *c, int begin, int end, int damp)
{
    ga2d_world *w = c->world;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        if (b->type != GA2D_BODY_DYNAMIC) continue;
        ga2d__verlet_kick(w, &b->sim, c->h / 2);
        if (damp) ga2d__damp(&b->sim, c->h);
        ga2d__cap_body(c, b, w->moving[k]);
    }
}

/* Verlet's opening half kick; and the closing one with the damping.  The
   closing one is capped too: uncapped, a stiff field (a drag of k h / m
   >> 2) left the step with any speed or turn, and the next step's
   contacts turned that into NaN. */
static void ga2d__open_kick(ga2d__step_context *c, int begin, int end) { ga2d__half_kicks(c, begin, end, 0); }
static void ga2d__close_kick(ga2d__step_context *c, int begin, int end) { ga2d__half_kicks(c, begin, end, 1); }

/* Whether some moving body lacks its cached field (Verlet). */
static int ga2d__field_stale(const ga2d_world *w)
{
    int k;
    for (k = 0; k < w->moving_count; ++k)
        if (!w->bodies[w->moving[k]].sim.field_valid) return 1;
    return 0;
}

/* The velocity phase of the world's integrator, at the substep's start. */
static void ga2d__integrate_velocities(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int n = w->moving_count, stage;
    if (w->def.integrator == GA2D_INTEGRATOR_RK4) {
        static const ga2d_real at[4] = {0, GA2D__R(0.5), GA2D__R(0.5), 1};
        static const ga2d_real weight[4] = {1, 2, 2, 1};
        GA2D_ASSERT(c->rk4_capacity >= n);
        c->masses_stale = 1; /* its stages move the bodies and put them back */
        ga2d__run(c, ga2d__rk4_begin, n);
        for (stage = 0; stage < 4; ++stage) {
            c->rk4_at = at[stage];
            c->rk4_weight = weight[stage];
            if (w->def.force_callback) {
                ga2d__run(c, ga2d__rk4_trial, n);
                ga2d__eval_field(w, c->t + (double)(at[stage] * c->h));
            }
            ga2d__run(c, ga2d__rk4_derive, n);
        }
        ga2d__run(c, ga2d__rk4_end, n);
    } else if (w->def.integrator == GA2D_INTEGRATOR_VERLET) {
        if (w->def.force_callback && ga2d__field_stale(w)) {
            ga2d__eval_field(w, c->t);
            ga2d__run(c, ga2d__cache_field, n);
        }
        ga2d__run(c, ga2d__open_kick, n);
    } else {
        ga2d__eval_field(w, c->t);
        ga2d__run_counted(c, ga2d__kick, n);
    }
}

/* Stage, over the moving bodies: RK4's displacement plus h times what
   the contacts changed, under the caps the velocities have (the stages'
   own velocities are not capped). */
static void ga2d__rk4_positions(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__rk4 *s = c->rk4;
    ga2d_real h = c->h;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        ga2d_real th = s[k].sth * (h / 6) + (b->sim.w - s[k].kw) * h;
        ga2d_vec d;
        b->sim.center = ga2d_vec_add(ga2d_vec_add(s[k].x0, ga2d_vec_scale(s[k].sx, h / 6)),
                                 ga2d_vec_scale(ga2d_vec_sub(b->sim.v, s[k].kv), h));
        d = ga2d_vec_sub(b->sim.center, s[k].x0);
        if (ga2d__cap_length(&d, GA2D__MAX_SPEED * w->def.length_units_per_meter * h)) b->sim.center = ga2d_vec_add(s[k].x0, d);
        b->sim.dp = ga2d_vec_sub(b->sim.center, b->sim.center0); /* RK4 places x itself */
        ga2d__cap_turn(&th, GA2D__MAX_TURN);
        if (th != 0) {
            b->sim.q = ga2d__turn(s[k].q0, th, w->def.rotation_update);
            ++w->counters.rotation_updates;
        }
        ++w->counters.integrated_bodies;
        /* a body contained in the velocity phase still has its stages'
           sums here: contain it again before the solver passes that
           follow can spread its NaN through the contacts */
        if (!ga2d__finite_vec(b->sim.center) || !ga2d__finite(b->sim.q.c) || !ga2d__finite(b->sim.q.s)) ga2d__contain(w, w->moving[k]);
    }
}

/* The caps again where they bound the motion, before the drift: the
   solver's passes (a joint's motor or feedback, a contact) may have driven
   a body past them since the kick, and a body moved at that speed tears
   its joints (a motor of 1e9 N m toward 1e4 rad/s turned a hinged bar 41
   rad a substep: its pin up to 43 m apart, a chain of five at 1e19 m).
   The velocity (v, w) is scaled as one, so the point that stood still (a
   pivot) still stands.  Counted in speed_caps when the solver went past
   a cap by more than the kick's own rounding of it (a rigid pass may
   take the speed back before the next kick sees it: a distance joint of
   absurd length pushing out at the cap, uncounted, for ever). */
static GA2D__HOT void ga2d__cap_motion(ga2d_vec *bv, ga2d_real *bw, ga2d_real max_speed, ga2d_real max_turn_rate, ga2d__counts *n)
{
    const ga2d_real slack = 1 + 16 * GA2D__EPS; /* above the kick's capped length, rounded */
    ga2d_vec v = *bv;
    ga2d_real om = *bw, s = 1;
    if (ga2d__cap_length(&v, max_speed * slack)) {
        ga2d_real m = GA2D__FABS(bv->x) > GA2D__FABS(bv->y) ? GA2D__FABS(bv->x) : GA2D__FABS(bv->y);
        v = *bv;
        (void)ga2d__cap_length(&v, max_speed);
        s = (GA2D__FABS(v.x) > GA2D__FABS(v.y) ? GA2D__FABS(v.x) : GA2D__FABS(v.y)) / m;
    }
    if (ga2d__cap_turn(&om, max_turn_rate) && om / *bw < s) s = om / *bw;
    if (s < 1) {
        *bv = ga2d_vec_scale(*bv, s);
        *bw *= s;
        ++n->speed_caps;
    }
}

/* Stage, over the moving bodies: the caps, x += h v, q <- q exp(w h e12). */
static void ga2d__drift_bodies(ga2d__step_context *c, int begin, int end)
{
    const ga2d_world *w = c->world;
    ga2d__body *bodies = w->bodies; /* in locals: see ga2d__gather */
    const int *moving = w->moving;
    const ga2d_real max_speed = GA2D__MAX_SPEED * w->def.length_units_per_meter, max_turn_rate = GA2D__MAX_TURN / c->h;
    ga2d__counts n = {0, 0, 0, 0, 0};
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &bodies[moving[k]];
        if (b->type == GA2D_BODY_DYNAMIC) ga2d__cap_motion(&b->sim.v, &b->sim.w, max_speed, max_turn_rate, &n);
        ga2d__drift(w, &b->sim, c->h, &n);
    }
    ga2d__counts_put(c, begin, &n);
}

/* Stage, over the moving bodies: ga2d__drift_bodies on the solver bodies
   (ga2d__compact_begin), and the solver's turn dq = q q0~ as
   ga2d__gather finds it; x = x0 + dp waits for ga2d__compact_end. */
static void ga2d__cdrift(ga2d__step_context *c, int begin, int end)
{
    const ga2d_world *w = c->world;
    const int *moving = w->moving;
    ga2d__kbody *kb = c->kbodies;
    ga2d__sbody *sb = c->sbodies;
    const ga2d_real h = c->h, max_speed = GA2D__MAX_SPEED * w->def.length_units_per_meter, max_turn_rate = GA2D__MAX_TURN / h;
    ga2d__counts n = {0, 0, 0, 0, 0};
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__kbody *r = &kb[k];
        ga2d__sbody *s = &sb[moving[k]];
        ga2d_vec v = ga2d_vec_make(s->vx, s->vy);
        ga2d_real om = s->w;
        ga2d_rotor q = r->q, dq;
        if (r->dynamic) {
            ga2d__cap_motion(&v, &om, max_speed, max_turn_rate, &n);
            s->vx = v.x;
            s->vy = v.y;
            s->w = om;
        }
        s->dpx += v.x * h;
        s->dpy += v.y * h;
        if (om != 0) {
            q = ga2d__turn(q, om * h, w->def.rotation_update);
            r->q = q;
            ++n.rotation_updates;
        }
        dq = ga2d_rotor_mul(q, ga2d_rotor_inverse(r->q0)); /* q from the register: read back from r, its
                                                               halves' stores stalled the load */
        s->dqc = dq.c;
        s->dqs = dq.s;
        ++n.integrated_bodies;
    }
    ga2d__counts_put(c, begin, &n);
}

/* Stage, over the moving bodies: their state back from the solver bodies
   and kbodies, after the substeps (ga2d__compact_begin). */
static void ga2d__cstore(ga2d__step_context *c, int begin, int end)
{
    ga2d__body *bodies = c->world->bodies;
    const int *moving = c->world->moving;
    const ga2d__kbody *kb = c->kbodies;
    const ga2d__sbody *sb = c->sbodies;
    int k;
    for (k = begin; k < end; ++k) {
        ga2d__body_sim *b = &bodies[moving[k]].sim;
        const ga2d__sbody *s = &sb[moving[k]];
        if (kb[k].dynamic) {
            b->v = ga2d_vec_make(s->vx, s->vy);
            b->w = s->w;
        }
        b->dp = ga2d_vec_make(s->dpx, s->dpy);
        b->center = ga2d_vec_add(b->center0, b->dp);
        b->q = kb[k].q;
    }
}

/* The position phase of the world's integrator, ending the substep. */
static void ga2d__integrate_positions(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int n = w->moving_count;
    c->masses_stale = 1;
    if (w->def.integrator == GA2D_INTEGRATOR_RK4) {
        ga2d__run(c, ga2d__rk4_positions, n);
        return;
    }
    ga2d__run_counted(c, ga2d__drift_bodies, n);
    if (w->def.integrator != GA2D_INTEGRATOR_VERLET) return;
    if (w->def.force_callback) {
        ga2d__eval_field(w, c->t + (double)c->h);
        ga2d__run(c, ga2d__cache_field, n);
    }
    ga2d__run(c, ga2d__close_kick, n);
}

/* ------------------------------------------------------ the substep plan */
/* A stage run once per substep (or `repeat` times in a row), over the
   whole of its kind. */
typedef void ga2d__stage_fn(ga2d__step_context *c);
typedef struct ga2d__stage { ga2d__stage_fn *run; int repeat; } ga2d__stage;
#define GA2D__MAX_STAGES 10

static void ga2d__stage_gather(ga2d__step_context *c) { ga2d__run_split(c, ga2d__gather, c->world->moving_count); }
static void ga2d__stage_scatter(ga2d__step_context *c) { ga2d__run_split(c, ga2d__scatter, c->world->moving_count); }

static int ga2d__min_int(int a, int b) { return a < b ? a : b; }

/* The soft step's stages over the bodies, joined (ga2d__joined):
   symplectic Euler's kick and the gather after it, with the last
   substep's scatter before them when it waited (ga2d__stage_kick_gather);
   the scatter after the soft pass, the drift and the gather before the
   relax pass.  Each block of bodies goes through all of them while it is
   in cache, where the stages one after
   another passed over every body two and three times a substep.  The
   same operations on the same bodies in the same order: the bits are
   those of the stages apart.  A body contained after the kick or drift
   (run_counted) was gathered as it was before: the solver bodies are then
   gathered again, as the stages apart had them (after the kick, this is
   what keeps a force's overflow from the body's neighbours). */
static void ga2d__joined(ga2d__step_context *c, int begin, int end, ga2d__range_fn *const *fns, int n)
{
    int k, stop, i;
    for (k = begin; k < end; k = stop) {
        stop = ga2d__min_int(k + GA2D__SPLIT_BLOCK, end);
        for (i = 0; i < n; ++i) fns[i](c, k, stop);
    }
}
static void ga2d__kick_gather(ga2d__step_context *c, int begin, int end)
{
    static ga2d__range_fn *const fns[] = {ga2d__kick, ga2d__gather};
    ga2d__joined(c, begin, end, fns, 2);
}
static void ga2d__scatter_kick_gather(ga2d__step_context *c, int begin, int end)
{
    static ga2d__range_fn *const fns[] = {ga2d__scatter, ga2d__kick, ga2d__gather};
    ga2d__joined(c, begin, end, fns, 3);
}
static void ga2d__scatter_drift_gather(ga2d__step_context *c, int begin, int end)
{
    static ga2d__range_fn *const fns[] = {ga2d__scatter, ga2d__drift_bodies, ga2d__gather};
    ga2d__joined(c, begin, end, fns, 3);
}

/* The soft step with symplectic Euler and no force callback integrates on
   the solver bodies and the kbodies beside them, and puts the bodies'
   state back once, after the substeps (ga2d__compact_end): nothing reads
   a body's record in between.  A substep passes over the bodies twice,
   the kick and the drift, reading 72 bytes a body (float) where the
   stages on the records (ga2d__kick_gather) read and wrote most of 232:
   a 22 000-body world's records do not stay in cache.  The same
   operations in the same order as those stages: the same bits.  Where
   memory runs out for the solver bodies, the step reports it and takes
   those stages. */
static int ga2d__compact_begin(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    c->compact = 0;
    if (w->def.solver != GA2D_SOLVER_SOFT_STEP || w->def.integrator != GA2D_INTEGRATOR_SYMPLECTIC_EULER ||
        w->def.force_callback || w->moving_count == 0)
        return 0;
    GA2D_ASSERT(c->kbody_capacity >= w->moving_count); /* ga2d__reserve_moving */
    if (!ga2d__reserve_slots(w, w->body_used)) {
        c->error = GA2D_ERR_OUT_OF_MEMORY; /* and the stages on the records run */
        return 0;
    }
    c->compact = c->compact_fresh = 1;
    return 1;
}
static void ga2d__compact_end(ga2d__step_context *c)
{
    if (!c->compact) return;
    ga2d__run_split(c, ga2d__cstore, c->world->moving_count);
    c->compact = 0;
}
static void ga2d__kload_range(ga2d__step_context *c, int begin, int end)
{
    int k;
    for (k = begin; k < end; ++k) ga2d__kload(c, k);
}
static void ga2d__load_kick(ga2d__step_context *c, int begin, int end)
{
    static ga2d__range_fn *const fns[] = {ga2d__kload_range, ga2d__ckick};
    ga2d__joined(c, begin, end, fns, 2);
}
static void ga2d__stage_ckick(ga2d__step_context *c)
{
    ga2d__range_fn *fn = c->compact_fresh ? ga2d__load_kick : ga2d__ckick;
    c->compact_fresh = 0;
    (void)ga2d__run_counted(c, fn, c->world->moving_count);
}
static void ga2d__stage_cdrift(ga2d__step_context *c)
{
    c->masses_stale = 1;
    (void)ga2d__run_counted(c, ga2d__cdrift, c->world->moving_count);
}

/* The relax pass's scatter waits for the next substep's kick (or the
   step's end, ga2d__scatter_if_due), unless a force callback is to read the
   bodies first. */
static void ga2d__scatter_if_due(ga2d__step_context *c)
{
    if (!c->scatter_due) return;
    c->scatter_due = 0;
    ga2d__stage_scatter(c);
}
static void ga2d__stage_defer_scatter(ga2d__step_context *c) { c->scatter_due = 1; }
static void ga2d__stage_kick_gather(ga2d__step_context *c)
{
    ga2d__range_fn *fn = c->scatter_due ? ga2d__scatter_kick_gather : ga2d__kick_gather;
    if (c->world->def.force_callback) {
        ga2d__scatter_if_due(c);
        fn = ga2d__kick_gather;
    }
    c->scatter_due = 0;
    ga2d__eval_field(c->world, c->t);
    if (ga2d__run_counted(c, fn, c->world->moving_count) > 0) ga2d__stage_gather(c);
}
static void ga2d__stage_drift_gather(ga2d__step_context *c)
{
    c->masses_stale = 1;
    if (ga2d__run_counted(c, ga2d__scatter_drift_gather, c->world->moving_count) > 0) ga2d__stage_gather(c);
}
/* A solver pass: its joints' and its lane groups' kernels, and whether
   the hit events' peaks are tracked after it (ga2d__pass_done). */
typedef struct ga2d__pass_kind {
    ga2d__range_fn *joints, *groups;
    int peaks;
} ga2d__pass_kind;

/* Blocks [start, end) of a pass's segment (ga2d__segments): a shared
   segment's joints' blocks come first, then its groups'. */
static void ga2d__segment_run(ga2d__step_context *c, const ga2d__segment *g, const ga2d__pass_kind *p, int start, int end)
{
    int jb = g->joint_blocks, first, stop;
    if (!g->shared) { /* one block, in order */
        if (g->joint_end > g->joint_begin) p->joints(c, g->joint_begin, g->joint_end);
        if (g->group_end > g->group_begin) p->groups(c, g->group_begin, g->group_end);
        return;
    }
    if (start < jb) {
        first = g->joint_begin + start * GA2D__JOINT_BLOCK;
        stop = ga2d__min_int(g->joint_begin + ga2d__min_int(end, jb) * GA2D__JOINT_BLOCK, g->joint_end);
        p->joints(c, first, stop);
    }
    if (end > jb) {
        first = g->group_begin + (start > jb ? start - jb : 0) * GA2D__GROUP_BLOCK;
        stop = ga2d__min_int(g->group_begin + (end - jb) * GA2D__GROUP_BLOCK, g->group_end);
        p->groups(c, first, stop);
    }
}
/* A shared segment of a pass handed to the workers as a job of its own. */
typedef struct ga2d__segment_task {
    ga2d__step_context *c;
    const ga2d__segment *segment;
    const ga2d__pass_kind *pass;
} ga2d__segment_task;
static void ga2d__segment_entry(int start, int end, int worker, void *context)
{
    const ga2d__segment_task *t = (const ga2d__segment_task *)context;
    (void)worker;
    ga2d__segment_run(t->c, t->segment, t->pass, start, end);
}

/* Segment n: joints [jb, je), then groups [gb, ge); shared, in blocks of
   GA2D__JOINT_BLOCK joints and GA2D__GROUP_BLOCK groups, else one block;
   returns n + 1. */
static int ga2d__segment_add(ga2d__step_context *c, int n, int jb, int je, int gb, int ge, int shared)
{
    ga2d__segment *g = &c->segments[n];
    GA2D_ASSERT(n < GA2D__SEGMENTS);
    g->joint_begin = jb;
    g->joint_end = je;
    g->group_begin = gb;
    g->group_end = ge;
    g->shared = shared;
    g->joint_blocks = shared ? (je - jb + GA2D__JOINT_BLOCK - 1) / GA2D__JOINT_BLOCK : 0;
    g->blocks = shared ? g->joint_blocks + (ge - gb + GA2D__GROUP_BLOCK - 1) / GA2D__GROUP_BLOCK : 1;
    return n + 1;
}
/* What runs here since the last segment, as one block: the joints of the
   colour that began it (none at first), then the groups from `here` to
   group `to`, if there is any. */
static int ga2d__segment_here(ga2d__step_context *c, int n, int jb, int je, int here, int to)
{
    if (je == jb && to == here) return n;
    return ga2d__segment_add(c, n, jb, je, here, to, 0);
}

/* Cuts the step's colours into the segments every solver pass runs one
   after the other, and returns how many are shared with the workers.  A
   colour of GA2D__COLOUR_MIN groups' worth, when there are workers, is a
   segment of its own in blocks of GA2D__JOINT_BLOCK joints and of
   GA2D__GROUP_BLOCK groups (no two of a colour move one body, so the
   blocks commute).  Between them, the colours run here follow one another
   in one block without a joint between them, so their groups (adjacent
   in colour order) run in one call, in the same order: a bin of a hundred
   mixed shapes has 20-30 colours of 1-5 groups, and a call per colour per
   pass (each sets up its constants first) cost it 2 % of its step.  Then
   the overflow's joints and groups, here. */
static int ga2d__segments(ga2d__step_context *c)
{
    const ga2d_world *w = c->world;
    int k, n = 0, shared = 0, here = 0, jb = 0, je = 0, colours = c->colour_count;
    int workers = w->def.worker_count > 1 && w->def.enqueue_task;
    for (k = 0; k <= colours; ++k) {
        int joint_end = k < colours ? c->joint_start[k + 1] : c->joint_active;
        int joints = joint_end - c->joint_start[k], groups = c->colour_start[k + (k < colours)] - c->colour_start[k];
        int blocks = (joints + GA2D__JOINT_BLOCK - 1) / GA2D__JOINT_BLOCK + (groups + GA2D__GROUP_BLOCK - 1) / GA2D__GROUP_BLOCK;
        if (k < colours && workers && blocks >= GA2D__COLOUR_MIN / GA2D__GROUP_BLOCK) {
            n = ga2d__segment_here(c, n, jb, je, here, c->colour_start[k]);
            n = ga2d__segment_add(c, n, c->joint_start[k], joint_end, c->colour_start[k], c->colour_start[k + 1], 1);
            ++shared;
            jb = je = 0;
            here = c->colour_start[k + 1];
        } else if (joints > 0) {
            n = ga2d__segment_here(c, n, jb, je, here, c->colour_start[k]);
            jb = c->joint_start[k];
            je = joint_end;
            here = c->colour_start[k];
        }
    }
    c->segment_count = ga2d__segment_here(c, n, jb, je, here, c->group_count);
    return shared;
}

/* After each solver pass: the lanes' anchors and masses are found at the
   bodies' positions now (ga2d__wfind), and with hit events each point's
   largest normal impulse of the step so far is kept. */
static void ga2d__track_peaks(ga2d__step_context *c, int begin, int end);
static void ga2d__pass_done(ga2d__step_context *c, const ga2d__pass_kind *p)
{
    c->masses_stale = 0;
    if (p->peaks && c->world->hit_shapes > 0) ga2d__run(c, ga2d__track_peaks, c->group_count);
}

/* ---- the solver's passes as one job: a team of the workers */
/* A colour handed to the workers as a job of its own costs a hand-off
   (4-5 us on the machine measured: large_pyramid has 6 such colours, 3
   passes and 4 substeps, 72 hand-offs a step, and two workers stepped it
   1.6-1.8 times as fast as one).  So the passes of a substep run as one
   job of worker_count members, each running every segment of every pass
   in turn: it takes blocks of the segment, first from its own share (the
   w-th of worker_count, so that a worker meets the same bodies in every
   pass and substep, in its own cache) and then from the others', and
   waits at the segment's end until every block taken is done.  A member
   waits only on blocks another member has taken, and so is running: a
   task system that runs the members one after the other, or fewer at
   once than the world's workers, lets the first do everything and the
   rest find it done.  The blocks of a segment commute (or it is one
   block), so the bits are those of any other cut.  It needs atomics:
   gcc's and clang's, here; elsewhere each colour is a job. */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(GA2D_NO_TEAM)
#define GA2D__TEAM 1
static int ga2d__atomic_add(int *p, int n) { return __atomic_fetch_add(p, n, __ATOMIC_ACQ_REL); }
static int ga2d__atomic_load(int *p) { return __atomic_load_n(p, __ATOMIC_ACQUIRE); }
static void ga2d__spin(void)
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    __asm__ __volatile__("yield");
#endif
}
#else
#define GA2D__TEAM 0
#endif
#define GA2D__LINE_INTS 16    /* a cache line of ints: shares' counters apart, so a member's own
                                 claims do not pull the line from the others */
#define GA2D__TEAM_SHARES 8   /* workers beyond share the shares */
#define GA2D__TEAM_CHUNKS 8   /* a member takes an eighth of a share at a time */

typedef struct ga2d__team {
    ga2d__step_context *c;
    const ga2d__pass_kind *passes;
    int pass_count, shares;
    int *lines;                  /* per pass and segment: a line per share (blocks taken of it),
                                    then a line of blocks done */
} ga2d__team;

#if GA2D__TEAM
/* Member `worker`'s part of segment g: the blocks it takes, from its own
   share first; returns how many it ran. */
static int ga2d__team_take(const ga2d__team *t, const ga2d__segment *g, const ga2d__pass_kind *p, int *line, int worker)
{
    int k, ran = 0, own = worker > 0 ? worker % t->shares : 0;
    for (k = 0; k < t->shares; ++k) {
        int share = (own + k) % t->shares, b;
        int lo = (int)((long long)g->blocks * share / t->shares), hi = (int)((long long)g->blocks * (share + 1) / t->shares);
        int chunk = (hi - lo + GA2D__TEAM_CHUNKS - 1) / GA2D__TEAM_CHUNKS;
        if (hi <= lo) continue;
        while ((b = lo + ga2d__atomic_add(&line[share * GA2D__LINE_INTS], chunk)) < hi) {
            int stop = ga2d__min_int(b + chunk, hi);
            ga2d__segment_run(t->c, g, p, b, stop);
            ran += stop - b;
        }
    }
    return ran;
}

static void ga2d__team_entry(int start, int end, int worker, void *context)
{
    const ga2d__team *t = (const ga2d__team *)context;
    ga2d__step_context *c = t->c;
    int n = c->segment_count, p, s;
    (void)start;
    (void)end;
    for (p = 0; p < t->pass_count; ++p)
        for (s = 0; s < n; ++s) {
            const ga2d__segment *g = &c->segments[s];
            int *line = t->lines + (size_t)(p * n + s) * (size_t)(t->shares + 1) * GA2D__LINE_INTS;
            int *done = line + t->shares * GA2D__LINE_INTS, last = s == n - 1;
            int ran = ga2d__team_take(t, g, &t->passes[p], line, worker);
            /* the member that finishes the pass's last segment closes the pass
               before the others may go on */
            if (ran > 0 && ga2d__atomic_add(done, ran) + ran == g->blocks && last) {
                ga2d__pass_done(c, &t->passes[p]);
                ga2d__atomic_add(done, 1);
            }
            while (ga2d__atomic_load(done) < g->blocks + last) ga2d__spin();
        }
}

/* The passes as one job of the workers; 0 if memory for its counters ran
   out (reported: the passes then run a colour a job, to the same bits). */
static int ga2d__team_run(ga2d__step_context *c, const ga2d__pass_kind *passes, int pass_count)
{
    const ga2d_world *w = c->world;
    ga2d__team t;
    void *handle;
    int lines;
    t.c = c;
    t.passes = passes;
    t.pass_count = pass_count;
    t.shares = ga2d__min_int(w->def.worker_count, GA2D__TEAM_SHARES);
    lines = pass_count * c->segment_count * (t.shares + 1);
    if (!ga2d__grow(&c->world->mem, (void **)&c->team_lines, &c->team_line_capacity, lines * GA2D__LINE_INTS, sizeof(int))) {
        c->error = GA2D_ERR_OUT_OF_MEMORY;
        return 0;
    }
    t.lines = c->team_lines;
    memset(t.lines, 0, (size_t)lines * GA2D__LINE_INTS * sizeof(int));
    handle = w->def.enqueue_task(ga2d__team_entry, w->def.worker_count, 1, &t, w->def.user_task_context);
    if (handle) w->def.finish_task(handle, w->def.user_task_context);
    return 1;
}
#endif

/* Solver passes one after the other, over the step's colours: on a team
   of the workers when a colour is long enough to share, else each
   segment shared with the workers as a job of its own or run here. */
static void ga2d__run_passes(ga2d__step_context *c, const ga2d__pass_kind *passes, int pass_count)
{
    const ga2d_world *w = c->world;
    int p, s, shared = ga2d__segments(c);
#if GA2D__TEAM
    if (shared > 0 && ga2d__team_run(c, passes, pass_count)) return;
#endif
    for (p = 0; p < pass_count; ++p) {
        for (s = 0; s < c->segment_count; ++s) {
            const ga2d__segment *g = &c->segments[s];
            ga2d__segment_task t;
            void *handle;
            if (!g->shared) {
                ga2d__segment_run(c, g, &passes[p], 0, g->blocks);
                continue;
            }
            t.c = c;
            t.segment = g;
            t.pass = &passes[p];
            handle = w->def.enqueue_task(ga2d__segment_entry, g->blocks, 1, &t, w->def.user_task_context);
            if (handle) w->def.finish_task(handle, w->def.user_task_context);
        }
        ga2d__pass_done(c, &passes[p]);
    }
}
static void ga2d__joints_biased(ga2d__step_context *c, int begin, int end) { ga2d__solve_joints(c, begin, end, 1); }
static void ga2d__joints_relaxed(ga2d__step_context *c, int begin, int end)
{
    ga2d__solve_joints(c, begin, end, c->joint_bias_in_relax);
}
/* Stage, over the groups, after each pass of a world with hit events:
   each point's largest normal impulse of the step so far (a body stopped
   in the first substep has none left by the last).  Kept out of the
   passes, which it slowed by 2 % with no hit event in the world. */
static void ga2d__track_peaks(ga2d__step_context *c, int begin, int end)
{
    int gi, k;
    for (gi = begin; gi < end; ++gi) {
        ga2d__group *g = &c->groups[gi];
        if (!g->hits) continue;
        for (k = 0; k < 2; ++k) g->x->npeak[k] = ga2d__wsel(ga2d__wgt(g->nimp[k], g->x->npeak[k]), g->nimp[k], g->x->npeak[k]);
    }
}

/* The passes (the warm start finds the lanes' anchors and masses,
   ga2d__wfind, as a pass does, and tracks no peak) */
static const ga2d__pass_kind ga2d__warm_pass = {ga2d__warm_start_joints, ga2d__warm_start, 0};
static const ga2d__pass_kind ga2d__soft_pass = {ga2d__joints_biased, ga2d__solve_soft, 1};
static const ga2d__pass_kind ga2d__relax_pass = {ga2d__joints_relaxed, ga2d__solve_rigid, 1};
static const ga2d__pass_kind ga2d__baumgarte_pass = {ga2d__joints_biased, ga2d__solve_baumgarte, 1};
static void ga2d__stage_warm_start(ga2d__step_context *c) { ga2d__run_passes(c, &ga2d__warm_pass, 1); }
static void ga2d__stage_solve(ga2d__step_context *c) { ga2d__run_passes(c, &ga2d__soft_pass, 1); }
/* The soft step's warm start and soft pass follow one another: one job. */
static void ga2d__stage_warm_solve(ga2d__step_context *c)
{
    ga2d__pass_kind both[2];
    both[0] = ga2d__warm_pass;
    both[1] = ga2d__soft_pass;
    ga2d__run_passes(c, both, 2);
}
static void ga2d__stage_relax(ga2d__step_context *c) { ga2d__run_passes(c, &ga2d__relax_pass, 1); }
static void ga2d__stage_baumgarte(ga2d__step_context *c) { ga2d__run_passes(c, &ga2d__baumgarte_pass, 1); }
static void ga2d__stage_push_apart(ga2d__step_context *c)
{
    c->masses_stale = 1;
    ga2d__run(c, ga2d__refresh_turns, c->world->moving_count);
    ga2d__run(c, ga2d__push_apart, c->constraint_count);
}

static int ga2d__plan_add(ga2d__stage *plan, int n, ga2d__stage_fn *run, int repeat)
{
    GA2D_ASSERT(n < GA2D__MAX_STAGES);
    plan[n].run = run;
    plan[n].repeat = repeat;
    return n + 1;
}

/* The substep as the world's solver kind has it (ga2d_solver):
   soft step   velocities, warm start, a soft pass, positions, a rigid
               relax pass;
   Baumgarte   velocities, warm start, velocity_iterations biased rigid
               passes, positions;
   NGS         velocities, warm start, velocity_iterations rigid passes,
               positions, position_iterations passes that push bodies
               apart.
   The solver passes work on the solver bodies, gathered before them and
   scattered after (the soft step with symplectic Euler joins those stages
   over the bodies: ga2d__kick_gather; without a force callback it
   integrates on the solver bodies themselves, `compact`:
   ga2d__compact_begin). */
static int ga2d__plan_substep(const ga2d_world *w, ga2d__stage *plan, int compact)
{
    int n = 0, soft = w->def.solver == GA2D_SOLVER_SOFT_STEP, ngs = w->def.solver == GA2D_SOLVER_PGS_NGS;
    int joined = soft && w->def.integrator == GA2D_INTEGRATOR_SYMPLECTIC_EULER; /* ga2d__kick_gather */
    if (compact) { /* ga2d__compact_begin */
        n = ga2d__plan_add(plan, n, ga2d__stage_ckick, 1);
        n = ga2d__plan_add(plan, n, w->def.enable_warm_starting ? ga2d__stage_warm_solve : ga2d__stage_solve, 1);
        n = ga2d__plan_add(plan, n, ga2d__stage_cdrift, 1);
        return ga2d__plan_add(plan, n, ga2d__stage_relax, 1);
    }
    n = ga2d__plan_add(plan, n, joined ? ga2d__stage_kick_gather : ga2d__integrate_velocities, 1);
    if (!joined) n = ga2d__plan_add(plan, n, ga2d__stage_gather, 1);
    if (soft) {
        n = ga2d__plan_add(plan, n, w->def.enable_warm_starting ? ga2d__stage_warm_solve : ga2d__stage_solve, 1);
    } else {
        if (w->def.enable_warm_starting) n = ga2d__plan_add(plan, n, ga2d__stage_warm_start, 1);
        n = ga2d__plan_add(plan, n, ngs ? ga2d__stage_relax : ga2d__stage_baumgarte, w->def.velocity_iterations);
    }
    if (!joined) {
        n = ga2d__plan_add(plan, n, ga2d__stage_scatter, 1);
        n = ga2d__plan_add(plan, n, ga2d__integrate_positions, 1);
    }
    if (soft) {
        n = ga2d__plan_add(plan, n, joined ? ga2d__stage_drift_gather : ga2d__stage_gather, 1);
        n = ga2d__plan_add(plan, n, ga2d__stage_relax, 1);
        n = ga2d__plan_add(plan, n, joined ? ga2d__stage_defer_scatter : ga2d__stage_scatter, 1);
    }
    if (ngs) n = ga2d__plan_add(plan, n, ga2d__stage_push_apart, w->def.position_iterations);
    return n;
}

/* ---------------------------------------------------- continuous collision */
/* A body is fast when its step's motion (its centre's displacement plus
   its turn times its reach) passes this fraction of its thinnest shape's
   inner reach: slower, it cannot cross a static shape within one step
   unseen, since the speculative contacts keep every point of it that can
   close the gap in a step. */
#define GA2D__CCD_FRACTION 0.5

typedef struct ga2d__ccd {
    ga2d_world *w;
    int slot;              /* the fast body */
    ga2d_sweep sweep;
    ga2d_real fraction;    /* the earliest impact found so far */
} ga2d__ccd;

/* A body's turn over the step that just ran, q q0~ (its dq is the
   solver's, refreshed per pass and not by every solver kind). */
static ga2d_rotor ga2d__step_turn(const ga2d__body *b) { return ga2d_rotor_mul(b->sim.q, ga2d_rotor_inverse(b->sim.q0)); }

/* Whether a body is fast: its step's motion, its centre's displacement
   plus its turn times its reach, passes GA2D__CCD_FRACTION of its
   thinnest shape's inner reach.  Most bodies are told slow without a
   square root or an arctangent: the turn is at most (pi/2) |sin| while
   cos >= 0 (sin t >= 2t/pi on [0, pi/2]), else at most pi. */
static int ga2d__is_fast(const ga2d__body *b)
{
    ga2d_vec d = ga2d_vec_sub(b->sim.center, b->sim.center0);
    ga2d_rotor dq = ga2d__step_turn(b);
    ga2d_real limit = GA2D__R(GA2D__CCD_FRACTION) * b->min_extent, d2 = ga2d_vec_length_sq(d), motion;
    ga2d_real turn_max = dq.c >= 0 ? GA2D__R(0.5) * GA2D__PI * GA2D__FABS(dq.s) : GA2D__PI, room = limit - turn_max * b->extent;
    if (room > 0 && d2 <= room * room) return 0;
    motion = GA2D__SQRT(d2) + GA2D__FABS(ga2d_rotor_angle(dq)) * b->extent;
    return motion > limit && ga2d__finite(motion);
}

/* A body's motion over the step that just ran: start to end. */
static ga2d_sweep ga2d__body_sweep(const ga2d__body *b)
{
    ga2d_sweep s;
    s.local_center = b->sim.local_center;
    s.c1 = b->sim.center0;
    s.c2 = b->sim.center;
    s.a1 = ga2d_rotor_angle(b->sim.q0);
    s.a2 = s.a1 + ga2d_rotor_angle(ga2d__step_turn(b));
    return s;
}

/* The middle of a shape: its proxy's points' mean. */
static ga2d_vec ga2d__proxy_middle(const ga2d_shape_proxy *p)
{
    ga2d_vec m = ga2d_vec_make(0, 0);
    int i;
    for (i = 0; i < p->count; ++i) m = ga2d_vec_add(m, p->points[i]);
    return ga2d_vec_scale(m, 1 / (ga2d_real)p->count);
}

/* Whether a fast body's centre came from a chain segment's front to
   within a slop of its line, or past it, in the step.  A one-sided
   segment stops only that: one that began behind it passes through, as
   in collision, and one that stays clear in front is held by its
   speculative contact. */
static int ga2d__crossed_chain(const ga2d_world *w, const ga2d__shape *s, const ga2d_sweep *sw)
{
    const ga2d_segment *seg = &s->geom.as.chain_segment.segment;
    ga2d_transform x = ga2d__body_xf(&w->bodies[s->body]);
    ga2d_vec p1 = ga2d_transform_apply(x, seg->point1), e = ga2d_vec_sub(ga2d_transform_apply(x, seg->point2), p1);
    ga2d_real front1 = ga2d_wedge(e, ga2d_vec_sub(sw->c1, p1)), front2 = ga2d_wedge(e, ga2d_vec_sub(sw->c2, p1));
    return front1 > 0 && front2 <= w->slop * ga2d_vec_length(e);
}

/* Whether the point m of the fast body (its frame) goes from one side of
   segment sp (the other body's frame, that body still) to the other over
   the sweep, across the segment's span. */
static int ga2d__middle_crosses(const ga2d_shape_proxy *sp, const ga2d_sweep *so, ga2d_vec m, const ga2d_sweep *sw)
{
    ga2d_transform xs = ga2d_sweep_transform(so, 0);
    ga2d_vec a = ga2d_transform_apply(xs, sp->points[0]), e = ga2d_vec_sub(ga2d_transform_apply(xs, sp->points[1]), a);
    ga2d_vec m1 = ga2d_vec_sub(ga2d_transform_apply(ga2d_sweep_transform(sw, 0), m), a);
    ga2d_vec m2 = ga2d_vec_sub(ga2d_transform_apply(ga2d_sweep_transform(sw, 1), m), a);
    ga2d_real s1 = ga2d_wedge(e, m1), s2 = ga2d_wedge(e, m2), t, along;
    if ((s1 > 0) == (s2 > 0) || s1 == s2) return 0;
    t = s1 / (s1 - s2);
    along = ga2d_dot(ga2d_vec_add(m1, ga2d_vec_scale(ga2d_vec_sub(m2, m1), t)), e);
    return along >= 0 && along <= ga2d_dot(e, e);
}

/* One shape met by the fast body's swept box, for each of the body's
   shapes.  First the shape's middle point is swept: a shape can pass
   through another only with its middle, and while the middle stays a
   slop clear the speculative contacts hold the surfaces (a box tumbling
   fast along the ground is left alone, and keeps its bits).  If the
   middle comes within GA2D_LINEAR_SLOP, the whole shape's time of impact
   is where it stops, or the middle's when the shapes already touched as
   the step began (a body pushed half into a thin wall, which a point
   more would carry through). */
static int ga2d__ccd_leaf(void *ctx, int k)
{
    ga2d__ccd *q = (ga2d__ccd *)ctx;
    ga2d_world *w = q->w;
    const ga2d__shape *s = &w->shapes[k];
    const ga2d__body *fast = &w->bodies[q->slot], *other = &w->bodies[s->body];
    ga2d_shape_proxy sp;
    ga2d_sweep so;
    int f;
    if (s->body == q->slot || s->is_sensor) return 1;
    if (other->type != GA2D_BODY_STATIC && !fast->is_bullet) return 1;
    if (s->geom.type == GA2D_SHAPE_CHAIN_SEGMENT && !ga2d__crossed_chain(w, s, &q->sweep)) return 1;
    sp = ga2d_shape_proxy_of(&s->geom);
    so = ga2d__body_sweep(other);
    if (other->type == GA2D_BODY_STATIC || !other->awake) so.c2 = so.c1, so.a2 = so.a1;
    for (f = fast->shape_head; f >= 0; f = w->shapes[f].next) {
        ga2d_shape_proxy fp, core;
        ga2d_toi_result mid, whole;
        ga2d_vec m;
        ga2d_real t;
        if (!ga2d__pair_wanted(w, f, k)) continue;
        fp = ga2d_shape_proxy_of(&w->shapes[f].geom);
        m = ga2d__proxy_middle(&fp);
        core = ga2d_make_proxy(&m, 1, 0);
        if (ga2d_time_of_impact(&sp, &so, &core, &q->sweep, w->slop, q->fraction, &mid) != GA2D_OK) continue;
        if (mid.state == GA2D_TOI_OVERLAPPED && sp.count == 2 && sp.radius == 0 && ga2d__middle_crosses(&sp, &so, m, &q->sweep))
            q->fraction = 0; /* pressed onto a segment, and through it: it stays */
        if (mid.state == GA2D_TOI_SEPARATED || mid.state == GA2D_TOI_OVERLAPPED) continue;
        if (ga2d_time_of_impact(&sp, &so, &fp, &q->sweep, w->slop, q->fraction, &whole) != GA2D_OK) continue;
        t = whole.state != GA2D_TOI_SEPARATED && whole.t > 0 ? whole.t : mid.t;
        if (t > 0 && t < q->fraction) q->fraction = t;
    }
    return 1;
}

/* Fast body `slot` swept (ga2d__continuous). */
static void ga2d__sweep_fast(ga2d__step_context *c, int slot)
{
    ga2d_world *w = c->world;
    int nodes = 0;
    ga2d__body *b = &w->bodies[slot];
    ga2d__ccd q;
    ga2d_aabb box;
    ++w->counters.continuous_bodies;
    q.w = w;
    q.slot = slot;
    q.sweep = ga2d__body_sweep(b);
    q.fraction = 1;
    /* all the body can cover: its centres' box grown by its reach */
    box.lower = box.upper = q.sweep.c1;
    {
        ga2d_aabb end;
        end.lower = end.upper = q.sweep.c2;
        box = ga2d__fatten(ga2d_aabb_union(box, end), b->extent + w->slop);
    }
    ga2d__tree_overlap(&w->trees[0], box, ga2d__ccd_leaf, &q, &nodes);
    if (b->is_bullet) ga2d__tree_overlap(&w->trees[1], box, ga2d__ccd_leaf, &q, &nodes);
    if (q.fraction < 1) {
        ga2d_transform x = ga2d_sweep_transform(&q.sweep, q.fraction);
        ++w->counters.continuous_hits;
        b->sim.q = x.q;
        b->sim.center = ga2d_vec_add(q.sweep.c1, ga2d_vec_scale(ga2d_vec_sub(q.sweep.c2, q.sweep.c1), q.fraction));
        b->sim.dp = ga2d_vec_sub(b->sim.center, b->sim.center0);
    }
}

/* After the substeps: each fast awake dynamic body (its bit in c->fast:
   ga2d__finish_bodies) is swept from where the step began to where it
   ended against static shapes (and, if a bullet, moving ones), in the
   moving list's order, and stopped at its earliest impact: put at the
   sweep's pose there, its velocity kept.  The rest of its step's motion
   is lost (1 - t of the step), as in Box2D; the next step's contacts
   take it from there.  Bodies that are not fast cost the motion test. */
static void ga2d__continuous(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    int k;
    w->counters.continuous_bodies = w->counters.continuous_hits = 0;
    for (k = ga2d__next_bit(c->fast, 0, w->moving_count); k >= 0; k = ga2d__next_bit(c->fast, k + 1, w->moving_count))
        ga2d__sweep_fast(c, w->moving[k]);
}

/* Stage, over the moving bodies (counted: ga2d__run_checked): the user's
   forces are spent; a body a contained neighbour's NaN reached
   (positions too: RK4's own stages, huge coordinates; and velocities: 0
   x NaN from a contact reaches kinematic bodies) is left to be contained
   after (ga2d__unfinite_state: it is put back where it began, so it is
   not fast); and, continuous collision on, each awake dynamic body with
   shapes that is fast (ga2d__is_fast) gets its bit in c->fast, for
   ga2d__continuous to sweep. */
static void ga2d__finish_bodies(ga2d__step_context *c, int begin, int end)
{
    ga2d_world *w = c->world;
    ga2d__counts n;
    int k, ccd = w->def.enable_continuous;
    memset(&n, 0, sizeof n);
    for (k = begin; k < end; ++k) {
        ga2d__body *b = &w->bodies[w->moving[k]];
        b->sim.force = ga2d_vec_make(0, 0);
        b->sim.torque = 0;
        if (!ga2d__state_finite(&b->sim)) ++n.unfinite;
        else if (ccd && b->type == GA2D_BODY_DYNAMIC && b->awake && b->shape_head >= 0 && ga2d__is_fast(b))
            c->fast[k >> 6] |= (uint64_t)1 << (k & 63);
    }
    ga2d__counts_put(c, begin, &n);
}
static int ga2d__unfinite_state(const ga2d__step_context *c, int k)
{
    return !ga2d__state_finite(&c->world->bodies[c->world->moving[k]].sim);
}

/* This step's sensor events: none begun; the ends from destruction since
   the last step come first. */
static void ga2d__sensor_events_begin(ga2d_world *w)
{
    int pending = w->sensor_end_pending;
    w->sensor_begin_count = 0;
    if (pending > 0) memmove(w->sensor_end, w->sensor_end + (w->sensor_end_count - pending), (size_t)pending * sizeof *w->sensor_end);
    w->sensor_end_count = pending;
    w->sensor_end_pending = 0;
    w->step.end_lost = w->sensor_end_lost;
    w->sensor_end_lost = 0;
}

/* The step's context: its times, what it reports, the contact softness.
   Contacts are softer than the substep can resolve at no more than a
   quarter of its rate, and twice as stiff against a body that cannot
   move (it takes none of the push). */
static void ga2d__step_begin(ga2d_world *w, ga2d_real dt, ga2d_real h)
{
    ga2d__step_context *c = &w->step;
    ga2d_real hz;
    c->world = w;
    c->dt = dt;
    c->h = h;
    c->inv_h = 1 / h;
    c->t0 = c->t = w->time;
    c->error = GA2D_OK;
    w->error_slot = -1;
    w->begin_count = w->end_count = w->hit_count = 0; /* this step's events */
    ga2d__sensor_events_begin(w);
    hz = w->def.contact_hertz < GA2D__HERTZ_CAP * c->inv_h ? w->def.contact_hertz : GA2D__HERTZ_CAP * c->inv_h;
    c->soft = ga2d__make_soft(hz, w->def.contact_damping_ratio, h);
    c->stiff = ga2d__make_soft(2 * hz, w->def.contact_damping_ratio, h);
    /* a rigid joint's feedback, at most a quarter of the substep rate as
       the contacts' (faster, a chain of welds rings and grows) */
    c->joint_soft = ga2d__make_soft(GA2D__JOINT_HERTZ < GA2D__HERTZ_CAP * c->inv_h ? GA2D__JOINT_HERTZ : GA2D__HERTZ_CAP * c->inv_h,
                                    GA2D__JOINT_DAMPING_RATIO, h);
    c->joint_bias_in_relax = w->def.solver != GA2D_SOLVER_SOFT_STEP;
    w->counters.integrated_bodies = 0;
    w->counters.force_evaluations = 0;
    w->counters.rotation_updates = 0;
    w->counters.speed_caps = 0;
    w->counters.sensor_tests = 0;
    w->counters.round_contacts = 0;
    w->counters.colouring_kept = 0;
    w->counters.boxes_kept = 0;
    w->counters.trees_rebuilt = 0;
}

/* Book-keeping after the impulses are stored: each constraint that
   reports hits and whose fastest approaching point pushed in any pass of
   the step (its peak impulse: a body stopped in the first substep has
   none left by the last), faster than the threshold, is a hit event. */
static void ga2d__hit_events(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    ga2d_real threshold = w->def.hit_event_threshold * w->def.length_units_per_meter;
    int i, k;
    for (i = 0; i < c->constraint_count; ++i) {
        const ga2d__contact_constraint *cc = &c->constraints[i];
        const ga2d__contact *ct = &w->contacts[cc->contact];
        int best = -1;
        if (!cc->hits) continue;
        for (k = 0; k < cc->count && k < ct->manifold.count; ++k)
            if (cc->p[k].approach > threshold && ct->peak[k] > 0 &&
                (best < 0 || cc->p[k].approach > cc->p[best].approach))
                best = k;
        if (best < 0) continue;
        if (!ga2d__grow(&w->mem, (void **)&w->hit_events, &w->hit_capacity, w->hit_count + 1, sizeof *w->hit_events)) {
            c->error = GA2D_ERR_OUT_OF_MEMORY;
            return;
        }
        {
            ga2d_contact_hit_event *e = &w->hit_events[w->hit_count++];
            e->shape_a = ga2d__shape_id_of(w, ct->shape_a);
            e->shape_b = ga2d__shape_id_of(w, ct->shape_b);
            e->point = ct->manifold.points[best].point;
            e->normal = ct->manifold.normal;
            e->approach_speed = cc->p[best].approach;
        }
    }
}

/* Book-keeping: the sleeping bodies the force field pushed in this step
   wake, with their islands, as ga2d_body_set_awake would wake them after
   it.  (Only steps with such a push pay for the walk over the slots.) */
static void ga2d__grant_wakes(ga2d_world *w)
{
    int i;
    for (i = 0; i < w->body_used && w->wake_requests > 0; ++i) {
        ga2d__body *b = &w->bodies[i];
        if (!b->wake_request) continue;
        b->wake_request = 0;
        --w->wake_requests;
        if (b->type >= 0) ga2d__wake(w, i);
    }
}

/* The step, stage by stage (a stage run with ga2d__run works over a range
   of its items; the others are book-keeping, in order). */
static void ga2d__step(ga2d_world *w, ga2d_real dt, ga2d_real h)
{
    ga2d__step_context *c = &w->step;
    ga2d__stage plan[GA2D__MAX_STAGES];
    int s, i, r, stages;
    ga2d__step_begin(w, dt, h);
    /* collision: fat boxes, new pairs, manifolds */
    ga2d__bits_zero(c->refits, w->moving_count);
    ga2d__run_counted(c, ga2d__mark_refits, w->moving_count);
    ga2d__refit_proxies(c);
    ga2d__run(c, ga2d__find_pairs, w->move_count);
    ga2d__create_pairs(c);
    if (ga2d__reserve_changes(c)) {
        ga2d__run_split(c, ga2d__collide_contacts, w->contact_used);
        ga2d__count_carried(c);
        ga2d__contact_changes(c);
    }
    ++w->box_clock; /* ga2d__boxes_unchanged */
    /* constraints, the collision phase, the lanes */
    ga2d__order_constraints(c); /* and prepares them, a block at a time */
    ga2d__run_split(c, ga2d__remember_start, w->moving_count);
    if (w->def.enable_restitution) ga2d__restitute(c);
    ga2d__order_joints(c);
    ga2d__run_split(c, ga2d__prepare_joints, c->joint_active);
    ga2d__assign_lanes(c); /* and colours the joints */
    ga2d__pack_hinges(c);
    w->counters.joints_solved = c->joint_active;
    w->counters.hinges_in_lanes = c->jgroup_count * GA2D__LANES;
    ga2d__run_split(c, ga2d__fill_groups, c->group_count);
    ga2d__run_split(c, ga2d__fill_hinges, c->jgroup_count);
    c->masses_stale = 1;
    /* the substeps */
    stages = ga2d__plan_substep(w, plan, ga2d__compact_begin(c));
    for (s = 0; s < w->def.substeps; ++s) {
        c->t = c->t0 + (double)h * s; /* no drift from summing h */
        for (i = 0; i < stages; ++i)
            for (r = 0; r < plan[i].repeat; ++r) plan[i].run(c);
    }
    ga2d__scatter_if_due(c);
    ga2d__compact_end(c);
    /* impulses kept for the next step, bodies finished, sleep */
    ga2d__run_split(c, ga2d__store_impulses, c->group_count);
    ga2d__run_split(c, ga2d__store_hinges, c->jgroup_count);
    c->group_count = c->colour_count = c->jgroup_count = 0;
    if (w->hit_shapes > 0) ga2d__hit_events(c);
    ga2d__bits_zero(c->fast, w->moving_count);
    (void)ga2d__run_checked(c, ga2d__finish_bodies, w->moving_count, ga2d__unfinite_state);
    if (w->def.enable_continuous) ga2d__continuous(c);
    else w->counters.continuous_bodies = w->counters.continuous_hits = 0;
    /* boxes for the queries between steps, and their pairs */
    ga2d__bits_zero(c->refits, w->moving_count);
    ga2d__run_split(c, ga2d__mark_strays, w->moving_count);
    ga2d__refit_proxies(c);
    if (w->move_count > 0) {
        ga2d__run(c, ga2d__find_pairs, w->move_count);
        ga2d__create_pairs(c);
    }
    w->counters.constraint_count = c->constraint_count;
    w->time = c->t0 + (double)dt;
    if (w->def.enable_sleep) ga2d__update_sleep(c);
    if (w->wake_requests > 0) ga2d__grant_wakes(w);
    if (w->sensor_count > 0) ga2d__update_sensors(c);
    ++w->counters.step_count;
}

GA2D_API ga2d_result ga2d_world_step(ga2d_world *w, ga2d_real dt)
{
    ga2d_real h;
    ga2d_result r;
    if (!w) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    if (!ga2d__finite(dt) || !(dt > 0)) return GA2D_ERR_INVALID_ARGUMENT;
    h = dt / (ga2d_real)w->def.substeps;
    if (!(h > 0)) return GA2D_ERR_INVALID_ARGUMENT; /* dt underflows when split */
    /* the bounds of GA2D_MAX_TIME_STEP: g h^2 is how far gravity moves a
       body from rest in a substep, before its contact pushes back */
    if (dt > GA2D__R(GA2D_MAX_TIME_STEP) || ga2d__length_times(w->def.gravity, h * h) > w->slop) return GA2D_ERR_TOO_LARGE;
    w->lock = GA2D__LOCK_STEP;
    ga2d__enter(w);
    ga2d__step(w, dt, h);
    r = w->step.end_lost ? GA2D_ERR_OUT_OF_MEMORY : w->step.error;
    w->lock = 0;
    ga2d__leave(w); /* destroyed from the force callback or an allocator hook: gone now */
    return r;
}

/* ================================================================ sleep */
/* The island of a dynamic body: it and the dynamic bodies joined to it by
   touching contacts and joints whose awake flag is `from`, each flipped as it is
   reached (the flag marks it as met), in w->wake_queue in the order met;
   returns their number.  The queue has room for every body slot. */
static int ga2d__flip_island(ga2d_world *w, int slot, int from)
{
    int head = 0, tail = 0;
    w->bodies[slot].awake = !from;
    w->wake_queue[tail++] = slot;
    while (head < tail) {
        int s = w->wake_queue[head++], link;
        for (link = ga2d__first_edge(w, s); link >= 0; link = ga2d__next_edge(w, link)) {
            const ga2d__contact *ct = &w->contacts[link >> 1];
            int other = ga2d__edge_other(w, link);
            ga2d__body *o = &w->bodies[other];
            if (!ct->touching || o->awake != from || o->type != GA2D_BODY_DYNAMIC) continue;
            o->awake = !from;
            w->wake_queue[tail++] = other;
        }
        for (link = ga2d__first_joint(w, s); link >= 0; link = ga2d__next_joint(w, link)) {
            int other = ga2d__joint_other(w, link);
            ga2d__body *o = &w->bodies[other];
            if (o->awake != from || o->type != GA2D_BODY_DYNAMIC) continue;
            o->awake = !from;
            w->wake_queue[tail++] = other;
        }
    }
    return tail;
}

/* Wakes a sleeping body and, through the touching contacts that sleeping
   bodies keep, its whole island. */
static void ga2d__wake(ga2d_world *w, int slot)
{
    ga2d__body *b = &w->bodies[slot];
    int n, i;
    if (b->awake || b->type != GA2D_BODY_DYNAMIC) {
        b->sleep_time = 0;
        return;
    }
    n = ga2d__flip_island(w, slot, 0);
    for (i = 0; i < n; ++i) {
        ga2d__body *x = &w->bodies[w->wake_queue[i]];
        x->sleep_time = 0;
        ga2d__moving_add(w, w->wake_queue[i]);
        x->sim.field_valid = 0;
    }
}

static void ga2d__put_to_sleep(ga2d_world *w, int slot)
{
    ga2d__body *b = &w->bodies[slot];
    b->awake = 0;
    b->sim.v = ga2d_vec_make(0, 0);
    b->sim.w = 0;
    /* its pose now is its start pose for as long as it sleeps: a body
       that touches it must see no motion of it */
    b->sim.center0 = b->sim.center;
    b->sim.q0 = b->sim.q;
    b->sim.dq = ga2d_rotor_identity();
    b->sim.force = ga2d_vec_make(0, 0);
    b->sim.torque = 0;
    ga2d__moving_remove(w, slot);
}

static int ga2d__find(ga2d_world *w, int s)
{
    while (w->bodies[s].island != s) {
        w->bodies[s].island = w->bodies[w->bodies[s].island].island; /* path halving */
        s = w->bodies[s].island;
    }
    return s;
}

/* Islands of awake dynamic bodies joined by touching contacts (static and
   kinematic bodies do not join them).  A body rests while max(|v|,
   extent |w|, |dp| / dt) stays under 5 cm/s (in metres); an island whose
   every body has rested for 0.5 s falls asleep and costs nothing until
   woken.  dp, the step's displacement, is there for a body being pushed
   out of an overlap: the relax pass takes the push-out speed out of v, so
   such a body looks at rest by v alone.  (An overlap's depth is no
   measure of that: a heavy load rests on its springs as deep as its mass
   ratio says, a 400:1 plank 8 slops, and is still.)  Book-keeping: it
   puts bodies to sleep. */
static void ga2d__update_sleep(ga2d__step_context *c)
{
    ga2d_world *w = c->world;
    ga2d_real dt = c->dt;
    ga2d_real tol = GA2D__SLEEP_SPEED * w->def.length_units_per_meter;
    int k, i, islands = 0;
    for (k = 0; k < w->moving_count; ++k) {
        int s = w->moving[k];
        ga2d__body *b = &w->bodies[s];
        ga2d_real speed2 = ga2d_dot(b->sim.v, b->sim.v), spin = b->extent * b->sim.w;
        b->island = s;
        if (b->type != GA2D_BODY_DYNAMIC) continue;
        if (speed2 > tol * tol || spin * spin > tol * tol || ga2d_dot(b->sim.dp, b->sim.dp) > tol * tol * dt * dt)
            b->sleep_time = 0;
        else b->sleep_time += dt;
    }
    for (i = 0; i < c->constraint_count; ++i) {
        const ga2d__contact_constraint *cc = &c->constraints[i];
        const ga2d__body *a = &w->bodies[cc->a], *b = &w->bodies[cc->b];
        int ra, rb;
        if (a->type != GA2D_BODY_DYNAMIC || b->type != GA2D_BODY_DYNAMIC || !a->awake || !b->awake) continue;
        ra = ga2d__find(w, cc->a);
        rb = ga2d__find(w, cc->b);
        if (ra != rb) w->bodies[ra > rb ? ra : rb].island = ra < rb ? ra : rb;
    }
    for (i = 0; i < c->joint_active; ++i) {
        /* joints join islands; a dynamic body on a moving kinematic one
           is carried, and does not rest */
        const ga2d__joint *j = &w->joints[c->joint_order[i]];
        ga2d__body *a = &w->bodies[j->body[0]], *b = &w->bodies[j->body[1]];
        int ra, rb;
        if (a->type == GA2D_BODY_KINEMATIC && (a->sim.v.x != 0 || a->sim.v.y != 0 || a->sim.w != 0)) b->sleep_time = 0;
        if (b->type == GA2D_BODY_KINEMATIC && (b->sim.v.x != 0 || b->sim.v.y != 0 || b->sim.w != 0)) a->sleep_time = 0;
        if (a->type != GA2D_BODY_DYNAMIC || b->type != GA2D_BODY_DYNAMIC || !a->awake || !b->awake) continue;
        ra = ga2d__find(w, j->body[0]);
        rb = ga2d__find(w, j->body[1]);
        if (ra != rb) w->bodies[ra > rb ? ra : rb].island = ra < rb ? ra : rb;
    }
    /* each root takes its island's shortest rest (a root is its own parent,
       and a kinematic body in the list is a root nothing joins) */
    for (k = 0; k < w->moving_count; ++k) {
        int s = w->moving[k];
        if (w->bodies[s].type == GA2D_BODY_DYNAMIC && ga2d__find(w, s) == s) {
            w->bodies[s].island_rest = w->bodies[s].sleep_time;
            ++islands;
        }
    }
    for (k = 0; k < w->moving_count; ++k) {
        int s = w->moving[k], r;
        if (w->bodies[s].type != GA2D_BODY_DYNAMIC) continue;
        r = ga2d__find(w, s);
        if (w->bodies[s].sleep_time < w->bodies[r].island_rest) w->bodies[r].island_rest = w->bodies[s].sleep_time;
    }
    w->counters.island_count = islands;
    /* moving_remove swaps the last entry in: walk down */
    for (k = w->moving_count - 1; k >= 0; --k) {
        int s = w->moving[k];
        if (w->bodies[s].type == GA2D_BODY_DYNAMIC && w->bodies[ga2d__find(w, s)].island_rest >= GA2D__TIME_TO_SLEEP)
            ga2d__put_to_sleep(w, s);
    }
}

/* ================================================================ queries */
/* A query locks the world while it runs (its callbacks are user code that
   must not move the trees under it) and counts what it visits; the world
   is const to the caller, not in memory, as for ga2d_world_draw. */
static ga2d_result ga2d__query_begin(const ga2d_world *cw, int has_callback, ga2d_world **out)
{
    ga2d_world *w = (ga2d_world *)cw;
    if (!w || !has_callback) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    w->lock = GA2D__LOCK_QUERY;
    w->counters.query_nodes = 0;
    w->counters.query_shapes = 0;
    ga2d__enter(w);
    *out = w;
    return GA2D_OK;
}

static void ga2d__query_end(ga2d_world *w)
{
    w->lock = 0;
    ga2d__leave(w);
}

/* Whether a query with filter f sees shape k. */
static int ga2d__query_sees(const ga2d_world *w, int k, ga2d_filter f)
{
    const ga2d__shape *s = &w->shapes[k];
    return !s->is_sensor && ga2d_should_collide(f, s->filter);
}

static ga2d_transform ga2d__shape_xf(const ga2d_world *w, int k) { return ga2d__body_xf(&w->bodies[w->shapes[k].body]); }

/* ------------------------------------------------------------------ rays */
typedef struct ga2d__ray_query {
    ga2d_world *w;
    ga2d_vec origin, translation;
    ga2d_filter filter;
    ga2d_cast_fn *fn;
    void *context;
    ga2d_ray_result closest; /* for the closest-hit form (fn NULL) */
} ga2d__ray_query;

/* One leaf: its shape's exact cast, handed to the callback or kept if
   closest; the ray is clipped to what the callback says (or to the
   closest hit so far). */
static int ga2d__ray_leaf(void *ctx, int k, ga2d_real *tmax)
{
    ga2d__ray_query *q = (ga2d__ray_query *)ctx;
    ga2d_world *w = q->w;
    ga2d_ray_result r;
    ga2d_real go_on;
    if (!ga2d__query_sees(w, k, q->filter)) return 1;
    ++w->counters.query_shapes;
    /* the whole ray, so a hit has the bits of ga2d_ray_cast_shape's; the
       clip only culls */
    r = ga2d__ray_placed(&w->shapes[k].geom, ga2d__shape_xf(w, k), q->origin, q->translation);
    if (!r.hit || r.fraction > *tmax) return 1;
    r.shape = ga2d__shape_id_of(w, k);
    r.body = ga2d__id_of(w, w->shapes[k].body);
    if (!q->fn) {
        q->closest = r;
        *tmax = r.fraction;
        return 1;
    }
    go_on = q->fn(r.shape, r.point, r.normal, r.fraction, q->context);
    if (go_on < 0 || !(go_on == go_on)) return 1; /* ignore this shape (NaN too) */
    if (go_on == 0) return 0;
    if (go_on < *tmax) *tmax = go_on;
    return 1;
}

static ga2d_result ga2d__ray_input_world(ga2d_vec origin, ga2d_vec translation)
{
    if (!ga2d__finite_vec(origin) || !ga2d__finite_vec(translation) || !ga2d__finite_vec(ga2d_vec_add(origin, translation)))
        return GA2D_ERR_NOT_FINITE;
    return translation.x == 0 && translation.y == 0 ? GA2D_ERR_INVALID_ARGUMENT : GA2D_OK;
}

/* Both trees, the static one first, the ray clipped as it goes. */
static void ga2d__ray_trees(ga2d__ray_query *q)
{
    ga2d_real tmax = 1;
    int k;
    for (k = 0; k < 2; ++k)
        if (!ga2d__tree_ray(&q->w->trees[k], q->origin, q->translation, &tmax, ga2d__ray_leaf, q, &q->w->counters.query_nodes))
            return;
}

GA2D_API ga2d_result ga2d_world_cast_ray(const ga2d_world *cw, ga2d_vec origin, ga2d_vec translation, ga2d_filter filter,
                                         ga2d_cast_fn *fn, void *context)
{
    ga2d__ray_query q;
    ga2d_world *w;
    ga2d_result r = ga2d__ray_input_world(origin, translation);
    if (r == GA2D_OK) r = ga2d__query_begin(cw, fn != NULL, &w);
    if (r != GA2D_OK) return r;
    memset(&q, 0, sizeof q);
    q.w = w;
    q.origin = origin;
    q.translation = translation;
    q.filter = filter;
    q.fn = fn;
    q.context = context;
    ga2d__ray_trees(&q);
    ga2d__query_end(w);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_cast_ray_closest_checked(const ga2d_world *cw, ga2d_vec origin, ga2d_vec translation,
                                                         ga2d_filter filter, ga2d_ray_result *out)
{
    ga2d__ray_query q;
    ga2d_world *w;
    ga2d_result r = ga2d__ray_input_world(origin, translation);
    if (r == GA2D_OK) r = ga2d__query_begin(cw, out != NULL, &w);
    if (r != GA2D_OK) return r;
    memset(&q, 0, sizeof q);
    q.w = w;
    q.origin = origin;
    q.translation = translation;
    q.filter = filter;
    ga2d__ray_trees(&q);
    ga2d__query_end(w);
    *out = q.closest;
    return GA2D_OK;
}

GA2D_API ga2d_ray_result ga2d_world_cast_ray_closest(const ga2d_world *w, ga2d_vec origin, ga2d_vec translation,
                                                     ga2d_filter filter)
{
    ga2d_ray_result r;
    memset(&r, 0, sizeof r);
    ga2d_world_cast_ray_closest_checked(w, origin, translation, filter, &r);
    return r;
}

/* -------------------------------------------------------------- overlaps */
typedef struct ga2d__overlap_query {
    ga2d_world *w;
    ga2d_aabb box;
    ga2d_vec point;
    int by_point;
    ga2d_filter filter;
    ga2d_overlap_fn *fn;
    void *context;
} ga2d__overlap_query;

/* The shape's own box, a chain segment's without the neighbour its
   broadphase box takes in. */
static ga2d_aabb ga2d__shape_tight_aabb(const ga2d__shape *s, ga2d_transform x)
{
    ga2d__shape seg;
    if (s->geom.type != GA2D_SHAPE_CHAIN_SEGMENT) return ga2d__shape_aabb(s, x);
    seg = *s;
    seg.geom.type = GA2D_SHAPE_SEGMENT;
    seg.geom.as.segment = s->geom.as.chain_segment.segment;
    return ga2d__shape_aabb(&seg, x);
}

/* Whether shape k contains world point c, its boundary included: c's
   distance from the shape's core (a circle's centre, a capsule's
   segment, a polygon: negative inside it) within the radius. */
static int ga2d__shape_contains(const ga2d_world *w, int k, ga2d_vec c)
{
    const ga2d_geometry *g = &w->shapes[k].geom;
    ga2d_vec p = ga2d_transform_apply_inv(ga2d__shape_xf(w, k), c), q, u;
    ga2d__hull h;
    int feature;
    switch (g->type) {
    case GA2D_SHAPE_CIRCLE:
        return ga2d_vec_length_sq(ga2d_vec_sub(p, g->as.circle.center)) <= g->as.circle.radius * g->as.circle.radius;
    case GA2D_SHAPE_CAPSULE:
        if (!ga2d__segment_hull(g->as.capsule.center1, g->as.capsule.center2, g->as.capsule.radius, &h))
            return ga2d_vec_length_sq(ga2d_vec_sub(p, g->as.capsule.center1)) <= g->as.capsule.radius * g->as.capsule.radius;
        return ga2d__hull_nearest(&h, p, &q, &u, &feature) <= h.radius;
    case GA2D_SHAPE_POLYGON:
        ga2d__polygon_hull(&g->as.polygon, ga2d_transform_identity(), 1, &h);
        return ga2d__hull_nearest(&h, p, &q, &u, &feature) <= h.radius;
    default: return 0; /* segments have no inside */
    }
}

static int ga2d__overlap_leaf(void *ctx, int k)
{
    ga2d__overlap_query *q = (ga2d__overlap_query *)ctx;
    ga2d_world *w = q->w;
    int in;
    if (!ga2d__query_sees(w, k, q->filter)) return 1;
    ++w->counters.query_shapes;
    in = q->by_point ? ga2d__shape_contains(w, k, q->point)
                     : ga2d_aabb_overlaps(ga2d__shape_tight_aabb(&w->shapes[k], ga2d__shape_xf(w, k)), q->box);
    return in ? q->fn(ga2d__shape_id_of(w, k), q->context) != 0 : 1;
}

static ga2d_result ga2d__overlap(const ga2d_world *cw, ga2d__overlap_query *q)
{
    ga2d_world *w;
    ga2d_result r = ga2d__query_begin(cw, q->fn != NULL, &w);
    int k;
    if (r != GA2D_OK) return r;
    q->w = w;
    for (k = 0; k < 2; ++k)
        if (!ga2d__tree_overlap(&w->trees[k], q->box, ga2d__overlap_leaf, q, &w->counters.query_nodes)) break;
    ga2d__query_end(w);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_overlap_aabb(const ga2d_world *w, ga2d_aabb box, ga2d_filter filter, ga2d_overlap_fn *fn,
                                             void *context)
{
    ga2d__overlap_query q;
    if (!ga2d__finite_vec(box.lower) || !ga2d__finite_vec(box.upper)) return GA2D_ERR_NOT_FINITE;
    if (!(box.lower.x <= box.upper.x && box.lower.y <= box.upper.y)) return GA2D_ERR_INVALID_ARGUMENT;
    memset(&q, 0, sizeof q);
    q.box = box;
    q.filter = filter;
    q.fn = fn;
    q.context = context;
    return ga2d__overlap(w, &q);
}

GA2D_API ga2d_result ga2d_world_overlap_point(const ga2d_world *w, ga2d_vec point, ga2d_filter filter,
                                              ga2d_overlap_fn *fn, void *context)
{
    ga2d__overlap_query q;
    if (!ga2d__finite_vec(point)) return GA2D_ERR_NOT_FINITE;
    memset(&q, 0, sizeof q);
    q.box.lower = q.box.upper = q.point = point;
    q.by_point = 1;
    q.filter = filter;
    q.fn = fn;
    q.context = context;
    return ga2d__overlap(w, &q);
}

/* ---------------------------------------------------------------- shapes */
typedef struct ga2d__shape_query {
    ga2d_world *w;
    const ga2d_shape_proxy *proxy;
    ga2d_transform x;
    ga2d_vec translation;
    ga2d_filter filter;
    ga2d_overlap_fn *overlap;
    ga2d_cast_fn *cast;
    void *context;
    ga2d_real tmax;
} ga2d__shape_query;

/* The box of a proxy placed by x, grown by its radius. */
static ga2d_aabb ga2d__proxy_box(const ga2d_shape_proxy *p, ga2d_transform x)
{
    ga2d_aabb b;
    int i;
    b.lower = b.upper = ga2d_transform_apply(x, p->points[0]);
    for (i = 1; i < p->count; ++i) {
        ga2d_aabb one;
        one.lower = one.upper = ga2d_transform_apply(x, p->points[i]);
        b = ga2d_aabb_union(b, one);
    }
    return ga2d__fatten(b, p->radius);
}

static int ga2d__overlap_shape_leaf(void *ctx, int k)
{
    ga2d__shape_query *q = (ga2d__shape_query *)ctx;
    ga2d_world *w = q->w;
    ga2d_shape_proxy sp;
    ga2d_distance_result d;
    if (!ga2d__query_sees(w, k, q->filter)) return 1;
    ++w->counters.query_shapes;
    sp = ga2d_shape_proxy_of(&w->shapes[k].geom);
    d = ga2d__distance(&sp, q->proxy, ga2d_transform_inv_mul(ga2d__shape_xf(w, k), q->x), NULL);
    return d.distance > 0 ? 1 : q->overlap(ga2d__shape_id_of(w, k), q->context) != 0;
}

static int ga2d__cast_shape_leaf(void *ctx, int k)
{
    ga2d__shape_query *q = (ga2d__shape_query *)ctx;
    ga2d_world *w = q->w;
    ga2d_shape_proxy sp;
    ga2d_transform xs;
    ga2d_ray_result c;
    ga2d_real go_on;
    if (!ga2d__query_sees(w, k, q->filter)) return 1;
    ++w->counters.query_shapes;
    sp = ga2d_shape_proxy_of(&w->shapes[k].geom);
    xs = ga2d__shape_xf(w, k);
    c = ga2d__shape_cast(&sp, q->proxy, ga2d_transform_inv_mul(xs, q->x), ga2d_rotate_inv(xs.q, q->translation),
                         w->slop / 4);
    if (!c.hit || c.fraction > q->tmax) return 1;
    c.point = ga2d_transform_apply(xs, c.point);
    c.normal = ga2d_rotate(xs.q, c.normal);
    go_on = q->cast(ga2d__shape_id_of(w, k), c.point, c.normal, c.fraction, q->context);
    if (go_on < 0 || !(go_on == go_on)) return 1;
    if (go_on == 0) return 0;
    if (go_on < q->tmax) q->tmax = go_on;
    return 1;
}

/* A world shape query's proxy and placement (translation: a cast's, or
   NULL).  Values not finite first; then the bounds a shape and a body
   keep: proxy points, radius, x's position and its end within
   GA2D_MAX_COORDINATE.  Past them GJK's squared lengths overflow (a point
   at 3e163 in double) and a hit's point comes out NaN. */
static ga2d_result ga2d__shape_query_input(const ga2d_shape_proxy *p, ga2d_transform x, const ga2d_vec *translation)
{
    ga2d_result r = ga2d__proxy_input(p);
    int i, bad = ga2d__collide_input(x, x, 1);
    if (r != GA2D_OK) return r;
    if (bad) return (ga2d_result)-bad;
    if (translation && (!ga2d__finite_vec(*translation) || !ga2d__finite_vec(ga2d_vec_add(x.p, *translation))))
        return GA2D_ERR_NOT_FINITE;
    for (i = 0; i < p->count && r == GA2D_OK; ++i) r = ga2d__point_check(p->points[i]);
    if (r == GA2D_OK) r = ga2d__radius_check(p->radius);
    if (r == GA2D_OK) r = ga2d__point_check(x.p);
    if (r == GA2D_OK && translation) r = ga2d__point_check(ga2d_vec_add(x.p, *translation));
    return r;
}

GA2D_API ga2d_result ga2d_world_overlap_shape(const ga2d_world *cw, const ga2d_shape_proxy *proxy, ga2d_transform x,
                                              ga2d_filter filter, ga2d_overlap_fn *fn, void *context)
{
    ga2d__shape_query q;
    ga2d_world *w;
    ga2d_result r = ga2d__shape_query_input(proxy, x, NULL);
    int k;
    if (r == GA2D_OK) r = ga2d__query_begin(cw, fn != NULL, &w);
    if (r != GA2D_OK) return r;
    memset(&q, 0, sizeof q);
    q.w = w;
    q.proxy = proxy;
    q.x = x;
    q.filter = filter;
    q.overlap = fn;
    q.context = context;
    for (k = 0; k < 2; ++k)
        if (!ga2d__tree_overlap(&w->trees[k], ga2d__proxy_box(proxy, x), ga2d__overlap_shape_leaf, &q, &w->counters.query_nodes))
            break;
    ga2d__query_end(w);
    return GA2D_OK;
}

GA2D_API ga2d_result ga2d_world_cast_shape(const ga2d_world *cw, const ga2d_shape_proxy *proxy, ga2d_transform x,
                                           ga2d_vec translation, ga2d_filter filter, ga2d_cast_fn *fn, void *context)
{
    ga2d__shape_query q;
    ga2d_world *w;
    ga2d_aabb from, to;
    ga2d_result r = ga2d__shape_query_input(proxy, x, &translation);
    int k;
    if (r == GA2D_OK) r = ga2d__query_begin(cw, fn != NULL, &w);
    if (r != GA2D_OK) return r;
    memset(&q, 0, sizeof q);
    q.w = w;
    q.proxy = proxy;
    q.x = x;
    q.translation = translation;
    q.filter = filter;
    q.cast = fn;
    q.context = context;
    q.tmax = 1;
    /* the swept box: where it starts and where it ends, and a slop more */
    from = ga2d__proxy_box(proxy, x);
    to = from;
    to.lower = ga2d_vec_add(to.lower, translation);
    to.upper = ga2d_vec_add(to.upper, translation);
    from = ga2d__fatten(ga2d_aabb_union(from, to), w->slop);
    for (k = 0; k < 2; ++k)
        if (!ga2d__tree_overlap(&w->trees[k], from, ga2d__cast_shape_leaf, &q, &w->counters.query_nodes)) break;
    ga2d__query_end(w);
    return GA2D_OK;
}

/* --------------------------------------------------------------- listing */
GA2D_API int ga2d_world_body_count(const ga2d_world *w) { return w ? w->body_count : 0; }

GA2D_API int ga2d_world_get_bodies(const ga2d_world *w, ga2d_body_id *ids, int capacity)
{
    int slot, n = 0;
    if (!w) return 0;
    for (slot = 0; slot < w->body_used; ++slot) {
        if (w->bodies[slot].type < 0) continue; /* a free slot */
        if (ids && n < capacity) ids[n] = ga2d__id_of(w, slot);
        ++n;
    }
    return n;
}

/* ============================================================= snapshots */
/* Layout: a header (magic, version, the build's real size and polygon
   size, the sizes of a body and a contact record, payload size, an FNV-1a
   checksum of the payload), then the payload: the world def (its pointers
   left out), time and counters, every body slot, every shape slot, each
   live shape's fat box, and the live contacts oldest first.  Everything is written field
   by field, so the library's structs may change without changing the
   format, and no padding byte is saved.  Loading validates all of it into
   a new world and swaps it in only when everything checked out; derived
   structures (trees, the moving list, the pair set, each body's contact
   list; its shape list is saved, as links, and checked) are rebuilt, and since the lists are rebuilt in creation order and
   pairs and the solver follow canonical orders, the loaded world steps bit
   for bit as the saved one. */
/* 2: body fields reordered (0.6.0); 3: held manifolds (0.8.0); 4: the
   world's id tag, body and def fields (0.8.1); 5: the def's cookie; 6:
   field by field (0.8.2); 7: shapes (0.9.0); 8: joints (0.10.0) */
#define GA2D__SNAP_VERSION 9u

typedef struct ga2d__snap_header {
    char magic[8];
    uint32_t version, real_size, max_vertices, body_size, contact_size, shape_size;
    uint64_t payload_size, checksum;
} ga2d__snap_header;

/* One list of fields serves saving, measuring (out NULL) and loading: a
   field is copied out of the world, counted, or read into it. */
typedef struct ga2d__codec {
    unsigned char *out;      /* saving: where the next byte goes (NULL: only count) */
    const unsigned char *in; /* loading: the payload */
    size_t n, at;            /* saving: bytes so far; loading: payload size, read so far */
    int loading, ok;         /* ok: 0 once a read ran past the end or met a bad count */
    size_t visitors_at;      /* loading: where the last sensor's visitors start */
} ga2d__codec;

/* A codec that saves to out (NULL: measures). */
static ga2d__codec ga2d__codec_writer(unsigned char *out)
{
    ga2d__codec k;
    memset(&k, 0, sizeof k);
    k.out = out;
    k.ok = 1;
    return k;
}

static void ga2d__io(ga2d__codec *k, void *p, size_t n)
{
    if (!k->loading) {
        if (k->out) memcpy(k->out + k->n, p, n);
        k->n += n;
    } else if (k->ok && k->n - k->at >= n) {
        memcpy(p, k->in + k->at, n);
        k->at += n;
    } else {
        memset(p, 0, n);
        k->ok = 0;
    }
}
static void ga2d__io_int(ga2d__codec *k, int *x) { ga2d__io(k, x, sizeof *x); }
static void ga2d__io_u32(ga2d__codec *k, uint32_t *x) { ga2d__io(k, x, sizeof *x); }
static void ga2d__io_u64(ga2d__codec *k, uint64_t *x) { ga2d__io(k, x, sizeof *x); }
static void ga2d__io_real(ga2d__codec *k, ga2d_real *x) { ga2d__io(k, x, sizeof *x); }
static void ga2d__io_double(ga2d__codec *k, double *x) { ga2d__io(k, x, sizeof *x); }
static void ga2d__io_vec(ga2d__codec *k, ga2d_vec *v)
{
    ga2d__io_real(k, &v->x);
    ga2d__io_real(k, &v->y);
}
static void ga2d__io_rotor(ga2d__codec *k, ga2d_rotor *q)
{
    ga2d__io_real(k, &q->c);
    ga2d__io_real(k, &q->s);
}
/* A count that sizes what follows: loading refuses one beyond max. */
static int ga2d__io_count(ga2d__codec *k, int *x, int max)
{
    ga2d__io_int(k, x);
    if (*x < 0 || *x > max) k->ok = 0;
    return k->ok;
}
/* An enum or flag kept as an int. */
#define GA2D__IO_ENUM(k, field, type)                                                                                     \
    do {                                                                                                                 \
        int v_ = (int)(field);                                                                                           \
        ga2d__io_int(k, &v_);                                                                                            \
        (field) = (type)v_;                                                                                              \
    } while (0)

static void ga2d__io_def(ga2d__codec *k, ga2d_world_def *d)
{
    ga2d__io_vec(k, &d->gravity);
    ga2d__io_int(k, &d->substeps);
    GA2D__IO_ENUM(k, d->integrator, ga2d_integrator);
    GA2D__IO_ENUM(k, d->rotation_update, ga2d_rotation_update);
    ga2d__io_real(k, &d->length_units_per_meter);
    GA2D__IO_ENUM(k, d->solver, ga2d_solver);
    ga2d__io_int(k, &d->velocity_iterations);
    ga2d__io_int(k, &d->position_iterations);
    ga2d__io_real(k, &d->contact_hertz);
    ga2d__io_real(k, &d->contact_damping_ratio);
    ga2d__io_real(k, &d->contact_push_max_velocity);
    ga2d__io_real(k, &d->restitution_threshold);
    ga2d__io_int(k, &d->enable_sleep);
    ga2d__io_int(k, &d->enable_warm_starting);
    ga2d__io_int(k, &d->enable_friction);
    ga2d__io_int(k, &d->enable_restitution);
    ga2d__io_int(k, &d->enable_continuous);
    ga2d__io_real(k, &d->hit_event_threshold);
    ga2d__io_int(k, &d->internal_cookie);
}

static void ga2d__io_counters(ga2d__codec *k, ga2d_world_counters *c)
{
    int64_t steps = (int64_t)c->step_count;
    ga2d__io_int(k, &c->body_count);
    ga2d__io_int(k, &c->moving_body_count);
    ga2d__io_int(k, &c->integrated_bodies);
    ga2d__io_int(k, &c->force_evaluations);
    ga2d__io_int(k, &c->rotation_updates);
    ga2d__io(k, &steps, sizeof steps);
    c->step_count = (long long)steps;
    ga2d__io_int(k, &c->pair_count);
    ga2d__io_int(k, &c->touching_count);
    ga2d__io_int(k, &c->constraint_count);
    ga2d__io_int(k, &c->awake_body_count);
    ga2d__io_int(k, &c->island_count);
    ga2d__io_int(k, &c->speed_caps);
    ga2d__io_int(k, &c->manifolds_carried);
    ga2d__io_int(k, &c->shape_count);
    ga2d__io_int(k, &c->sensor_tests);
    ga2d__io_int(k, &c->round_contacts);
    ga2d__io_int(k, &c->joint_count);
    ga2d__io_int(k, &c->joints_solved);
}

/* A live joint's lasting fields (what is prepared each step is not). */
static void ga2d__io_joint(ga2d__codec *k, ga2d__joint *j)
{
    int s;
    for (s = 0; s < 2; ++s) {
        ga2d__io_int(k, &j->body[s]);
        ga2d__io_vec(k, &j->local[s]);
    }
    ga2d__io_u64(k, &j->serial);
    ga2d__io_int(k, &j->collide_connected);
    ga2d__io_real(k, &j->reference_angle);
    ga2d__io_real(k, &j->lower);
    ga2d__io_real(k, &j->upper);
    ga2d__io_real(k, &j->motor_speed);
    ga2d__io_real(k, &j->max_motor);
    ga2d__io_real(k, &j->hertz);
    ga2d__io_real(k, &j->damping_ratio);
    ga2d__io_int(k, &j->enable_limit);
    ga2d__io_int(k, &j->enable_motor);
    ga2d__io_int(k, &j->enable_spring);
    ga2d__io_vec(k, &j->linear_impulse);
    ga2d__io_real(k, &j->spring_impulse);
    ga2d__io_real(k, &j->motor_impulse);
    ga2d__io_real(k, &j->lower_impulse);
    ga2d__io_real(k, &j->upper_impulse);
    ga2d__io_real(k, &j->impulse);
    ga2d__io_real(k, &j->length);
    ga2d__io_real(k, &j->linear_hertz);
    ga2d__io_real(k, &j->linear_damping_ratio);
    ga2d__io_real(k, &j->max_force);
    ga2d__io_real(k, &j->max_torque);
    ga2d__io_real(k, &j->correction);
    ga2d__io_vec(k, &j->offset);
    {
        uint64_t user = (uint64_t)(uintptr_t)j->user_data;
        ga2d__io_u64(k, &user); /* restored as saved, as a body's: see ga2d_world_snapshot_load */
        j->user_data = (void *)(uintptr_t)user;
    }
}

static void ga2d__io_polygon(ga2d__codec *k, ga2d_polygon *p)
{
    int i;
    if (!ga2d__io_count(k, &p->count, GA2D_MAX_POLYGON_VERTICES)) return;
    for (i = 0; i < p->count; ++i) {
        ga2d__io_vec(k, &p->vertices[i]);
        ga2d__io_vec(k, &p->normals[i]);
    }
    ga2d__io_real(k, &p->radius);
}

/* A body slot: a free one is its type, link and generation; a live one
   everything but what loading rebuilds (its proxy, lists, island and
   moving-list place) and what lives only inside a step. */
static void ga2d__io_body(ga2d__codec *k, ga2d__body *b)
{
    uint64_t user = (uint64_t)(uintptr_t)b->user_data;
    ga2d__io_int(k, &b->type);
    ga2d__io_int(k, &b->next_free);
    ga2d__io_u32(k, &b->generation);
    if (b->type < 0) return;
    ga2d__io_vec(k, &b->sim.center);
    ga2d__io_rotor(k, &b->sim.q);
    ga2d__io_vec(k, &b->sim.v);
    ga2d__io_real(k, &b->sim.w);
    ga2d__io_vec(k, &b->sim.center0);
    ga2d__io_rotor(k, &b->sim.q0);
    ga2d__io_rotor(k, &b->sim.dq);
    ga2d__io_real(k, &b->mass);
    ga2d__io_real(k, &b->sim.inv_mass);
    ga2d__io_real(k, &b->inertia);
    ga2d__io_real(k, &b->sim.inv_inertia);
    ga2d__io_vec(k, &b->sim.local_center);
    ga2d__io_real(k, &b->extent);
    ga2d__io_real(k, &b->min_extent);
    ga2d__io_int(k, &b->is_bullet);
    ga2d__io_int(k, &b->awake);
    ga2d__io_int(k, &b->fixed_rotation);
    ga2d__io_int(k, &b->shape_head);
    ga2d__io_int(k, &b->shape_tail);
    ga2d__io_int(k, &b->shape_count);
    ga2d__io_vec(k, &b->sim.force);
    ga2d__io_real(k, &b->sim.torque);
    ga2d__io_real(k, &b->sim.gravity_scale);
    ga2d__io_real(k, &b->sim.linear_damping);
    ga2d__io_real(k, &b->sim.angular_damping);
    ga2d__io_vec(k, &b->sim.field_force);
    ga2d__io_real(k, &b->sim.field_torque);
    ga2d__io_vec(k, &b->sim.field_accel);
    ga2d__io_real(k, &b->sim.field_alpha);
    ga2d__io_int(k, &b->sim.field_valid);
    ga2d__io_real(k, &b->sleep_time);
    ga2d__io_real(k, &b->island_rest);
    ga2d__io_u64(k, &user); /* restored as saved: see ga2d_world_snapshot_load */
    b->user_data = (void *)(uintptr_t)user;
}

/* A sensor's visitors: their count and slots.  Loading reads them into
   the codec's scratch (the world being loaded allocates them after). */
static void ga2d__io_visitors(ga2d__codec *k, ga2d__shape *s)
{
    int i, n = s->visitor_count;
    ga2d__io_int(k, &n);
    if (k->loading) {
        /* each takes an int of what is left: a count beyond that is damage */
        if (n < 0 || (size_t)n > (k->n - k->at) / sizeof(int)) {
            k->ok = 0;
            return;
        }
        s->visitor_count = n;
        s->visitors = NULL;
        s->visitor_capacity = 0;
        k->visitors_at = k->at; /* read again when the array exists */
        k->at += (size_t)n * sizeof(int);
        return;
    }
    for (i = 0; i < n; ++i) ga2d__io_int(k, &s->visitors[i]);
}

/* A shape slot: a free one is its type, link and generation; a live one
   its body and list link, queue flag, material, filter, user data and
   geometry (its proxy is rebuilt). */
static void ga2d__io_shape(ga2d__codec *k, ga2d__shape *s)
{
    uint64_t user = (uint64_t)(uintptr_t)s->user_data;
    ga2d_geometry *g = &s->geom;
    ga2d__io_int(k, &s->type);
    ga2d__io_int(k, &s->next_free);
    ga2d__io_u32(k, &s->generation);
    if (s->type < 0) return;
    ga2d__io_int(k, &s->body);
    ga2d__io_int(k, &s->next);
    ga2d__io_int(k, &s->in_move);
    ga2d__io_real(k, &s->density);
    ga2d__io_real(k, &s->friction);
    ga2d__io_real(k, &s->restitution);
    ga2d__io_u32(k, &s->filter.category_bits);
    ga2d__io_u32(k, &s->filter.mask_bits);
    ga2d__io(k, &s->filter.group_index, sizeof s->filter.group_index);
    ga2d__io_u64(k, &user);
    s->user_data = (void *)(uintptr_t)user;
    ga2d__io_int(k, &s->is_sensor);
    ga2d__io_int(k, &s->sensor_events);
    ga2d__io_int(k, &s->pre_solve_events);
    ga2d__io_int(k, &s->hit_events);
    ga2d__io_real(k, &s->tangent_speed);
    ga2d__io_real(k, &s->rolling_resistance);
    g->type = (ga2d_shape_type)s->type;
    if (k->loading) s->chain = -1;
    switch (s->type) {
    case GA2D_SHAPE_POLYGON: ga2d__io_polygon(k, &g->as.polygon); break;
    case GA2D_SHAPE_CIRCLE:
        ga2d__io_vec(k, &g->as.circle.center);
        ga2d__io_real(k, &g->as.circle.radius);
        break;
    case GA2D_SHAPE_CAPSULE:
        ga2d__io_vec(k, &g->as.capsule.center1);
        ga2d__io_vec(k, &g->as.capsule.center2);
        ga2d__io_real(k, &g->as.capsule.radius);
        break;
    case GA2D_SHAPE_SEGMENT:
        ga2d__io_vec(k, &g->as.segment.point1);
        ga2d__io_vec(k, &g->as.segment.point2);
        break;
    case GA2D_SHAPE_CHAIN_SEGMENT:
        ga2d__io_vec(k, &g->as.chain_segment.ghost1);
        ga2d__io_vec(k, &g->as.chain_segment.segment.point1);
        ga2d__io_vec(k, &g->as.chain_segment.segment.point2);
        ga2d__io_vec(k, &g->as.chain_segment.ghost2);
        ga2d__io_int(k, &s->chain);
        break;
    default: k->ok = 0; break;
    }
    if (s->is_sensor == 1 && k->ok) ga2d__io_visitors(k, s);
}

static void ga2d__io_manifold(ga2d__codec *k, ga2d_manifold *m)
{
    int i;
    ga2d__io_vec(k, &m->normal);
    if (!ga2d__io_count(k, &m->count, 2)) return;
    for (i = 0; i < m->count; ++i) {
        ga2d_manifold_point *p = &m->points[i];
        ga2d__io_vec(k, &p->point);
        ga2d__io_vec(k, &p->anchor_a);
        ga2d__io_vec(k, &p->anchor_b);
        ga2d__io_real(k, &p->separation);
        ga2d__io_real(k, &p->normal_impulse);
        ga2d__io_real(k, &p->tangent_impulse);
        ga2d__io_u32(k, &p->id);
        ga2d__io_int(k, &p->persisted);
    }
}

/* A contact: what its creation cannot recompute.  The held manifold only
   while touching (nothing reads it otherwise). */
static void ga2d__io_contact(ga2d__codec *k, ga2d__contact *c)
{
    int i;
    ga2d__io_int(k, &c->shape_a);
    ga2d__io_int(k, &c->shape_b);
    ga2d__io_u64(k, &c->serial);
    ga2d__io_int(k, &c->touching);
    ga2d__io_real(k, &c->friction);
    ga2d__io_real(k, &c->restitution);
    ga2d__io_manifold(k, &c->manifold);
    if (!c->touching || !k->ok) return;
    ga2d__io_vec(k, &c->held.rel.p);
    ga2d__io_rotor(k, &c->held.rel.q);
    ga2d__io_vec(k, &c->held.normal);
    for (i = 0; i < c->manifold.count; ++i) {
        ga2d__io_vec(k, &c->held.point[i]);
        ga2d__io_real(k, &c->held.separation[i]);
    }
}

static uint64_t ga2d__fnv1a(const unsigned char *p, size_t n)
{
    uint64_t h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

/* The header; the record sizes are those of a live body, of a live
   polygon shape with a full polygon and of a touching contact with two
   points, as written. */
static ga2d__snap_header ga2d__snap_header_make(uint64_t payload)
{
    ga2d__snap_header h;
    ga2d__codec k;
    ga2d__body b;
    ga2d__shape s;
    ga2d__contact c;
    memset(&h, 0, sizeof h);
    k = ga2d__codec_writer(NULL);
    memset(&b, 0, sizeof b);
    memset(&s, 0, sizeof s);
    memset(&c, 0, sizeof c);
    s.type = GA2D_SHAPE_POLYGON;
    s.geom.as.polygon.count = GA2D_MAX_POLYGON_VERTICES;
    c.touching = 1;
    c.manifold.count = 2;
    memcpy(h.magic, "GA2DSNAP", 8);
    h.version = GA2D__SNAP_VERSION;
    h.real_size = (uint32_t)sizeof(ga2d_real);
    h.max_vertices = (uint32_t)GA2D_MAX_POLYGON_VERTICES;
    ga2d__io_body(&k, &b);
    h.body_size = (uint32_t)k.n;
    k.n = 0;
    ga2d__io_shape(&k, &s);
    h.shape_size = (uint32_t)k.n;
    k.n = 0;
    ga2d__io_contact(&k, &c);
    h.contact_size = (uint32_t)k.n;
    h.payload_size = payload;
    return h;
}

/* A live contact's age, for saving them oldest first. */
typedef struct ga2d__snap_order { uint64_t serial; int index; } ga2d__snap_order;

static int ga2d__cmp_serial(const void *x, const void *y)
{
    uint64_t a = ((const ga2d__snap_order *)x)->serial, b = ((const ga2d__snap_order *)y)->serial;
    return (a > b) - (a < b);
}

/* Writes (or, with k->out NULL, measures) the payload; the live contacts'
   order comes from `order` (contact_count entries, unused when measuring). */
static void ga2d__snap_payload(const ga2d_world *w, ga2d__codec *k, ga2d__snap_order *order)
{
    ga2d_world_def d = w->def;
    ga2d_world_counters counters = w->counters;
    double time = w->time;
    ga2d_real dt = w->step.dt;
    uint32_t tag = w->tag;
    uint64_t serial = w->contact_serial;
    int used = w->body_used, free_head = w->free_head, count = w->body_count, contacts = w->contact_count, i, n = 0;
    ga2d__io_def(k, &d);
    ga2d__io_double(k, &time);
    ga2d__io_real(k, &dt);
    ga2d__io_counters(k, &counters);
    ga2d__io_u32(k, &tag);
    ga2d__io_int(k, &used);
    ga2d__io_int(k, &free_head);
    ga2d__io_int(k, &count);
    for (i = 0; i < w->body_used; ++i) {
        ga2d__body b = w->bodies[i];
        ga2d__io_body(k, &b);
    }
    used = w->shape_used;
    free_head = w->shape_free;
    count = w->shape_count;
    ga2d__io_int(k, &used);
    ga2d__io_int(k, &free_head);
    ga2d__io_int(k, &count);
    for (i = 0; i < w->shape_used; ++i) {
        ga2d__shape sh = w->shapes[i];
        ga2d__io_shape(k, &sh);
    }
    for (i = 0; i < w->shape_used; ++i) {
        const ga2d__shape *sh = &w->shapes[i];
        if (sh->type >= 0) {
            ga2d_aabb box = ga2d__fat_box(w, sh);
            ga2d__io_vec(k, &box.lower);
            ga2d__io_vec(k, &box.upper);
        }
    }
    used = w->chain_used;
    free_head = w->chain_free;
    count = w->chain_count;
    ga2d__io_int(k, &used);
    ga2d__io_int(k, &free_head);
    ga2d__io_int(k, &count);
    for (i = 0; i < w->chain_used; ++i) {
        ga2d__chain c = w->chains[i];
        int j;
        ga2d__io_int(k, &c.type);
        ga2d__io_int(k, &c.next_free);
        ga2d__io_u32(k, &c.generation);
        if (c.type < 0) continue;
        ga2d__io_int(k, &c.body);
        ga2d__io_int(k, &c.count);
        for (j = 0; j < c.count; ++j) ga2d__io_int(k, &c.shapes[j]);
    }
    {
        uint64_t joint_serial = w->joint_serial;
        used = w->joint_used;
        free_head = w->joint_free;
        count = w->joint_count;
        ga2d__io_int(k, &used);
        ga2d__io_int(k, &free_head);
        ga2d__io_int(k, &count);
        ga2d__io_u64(k, &joint_serial);
        for (i = 0; i < w->joint_used; ++i) {
            ga2d__joint jt = w->joints[i];
            ga2d__io_int(k, &jt.type);
            ga2d__io_int(k, &jt.next_free);
            ga2d__io_u32(k, &jt.generation);
            if (jt.type >= 0) ga2d__io_joint(k, &jt);
        }
    }
    ga2d__io_u64(k, &serial);
    ga2d__io_int(k, &contacts);
    for (i = 0; i < w->contact_used; ++i) {
        if (w->contacts[i].next_free != -2) continue;
        if (!order) { /* measuring: a contact's size is its own, in any order */
            ga2d__contact c = w->contacts[i];
            ga2d__io_contact(k, &c);
            continue;
        }
        order[n].serial = w->contacts[i].serial;
        order[n++].index = i;
    }
    if (n > 1) qsort(order, (size_t)n, sizeof *order, ga2d__cmp_serial);
    for (i = 0; i < n; ++i) {
        ga2d__contact c = w->contacts[order[i].index];
        ga2d__io_contact(k, &c);
    }
}

GA2D_API size_t ga2d_world_snapshot_size(const ga2d_world *w)
{
    ga2d__codec k;
    if (!w) return 0;
    k = ga2d__codec_writer(NULL);
    ga2d__snap_payload(w, &k, NULL);
    return sizeof(ga2d__snap_header) + k.n;
}

GA2D_API ga2d_result ga2d_world_snapshot_save(const ga2d_world *w, void *buf, size_t cap)
{
    ga2d__snap_order *order = NULL;
    ga2d__snap_header h;
    ga2d__codec k;
    size_t size, order_bytes;
    if (!w || !buf) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    size = ga2d_world_snapshot_size(w);
    if (cap < size) return GA2D_ERR_BUFFER_TOO_SMALL;
    k = ga2d__codec_writer((unsigned char *)buf + sizeof h);
    order_bytes = (size_t)w->contact_count * sizeof *order;
    if (order_bytes > 0) {
        /* the world is const to the caller, not in memory: its lock and
           depth count the user code that the allocator hooks run */
        ga2d_world *mw = (ga2d_world *)w;
        ga2d__enter(mw);
        order = (ga2d__snap_order *)ga2d__alloc(&mw->mem, order_bytes);
        if (order) {
            ga2d__snap_payload(w, &k, order);
            ga2d__free(&mw->mem, order, order_bytes);
        }
        ga2d__leave(mw); /* nothing below reads the world */
        if (!order) return GA2D_ERR_OUT_OF_MEMORY;
    } else {
        ga2d__snap_order none;
        ga2d__snap_payload(w, &k, &none);
    }
    h = ga2d__snap_header_make((uint64_t)k.n);
    h.checksum = ga2d__fnv1a(k.out, k.n);
    memcpy(buf, &h, sizeof h);
    return GA2D_OK;
}

/* A saved body is one the library could have made: finite state, a unit
   rotor, flags that are flags.  (Free slots: only their link is used.) */
static int ga2d__snap_body_ok(const ga2d__body *b, int body_used)
{
    const ga2d_real *r[] = {&b->sim.center.x, &b->sim.center.y, &b->sim.q.c, &b->sim.q.s, &b->sim.v.x, &b->sim.v.y, &b->sim.w, &b->sim.force.x,
                            &b->sim.force.y, &b->sim.torque, &b->sim.field_force.x, &b->sim.field_force.y, &b->sim.field_torque,
                            &b->sim.field_accel.x, &b->sim.field_accel.y, &b->sim.field_alpha, &b->mass, &b->sim.inv_mass, &b->inertia,
                            &b->sim.inv_inertia, &b->sim.local_center.x, &b->sim.local_center.y,
                            &b->sim.linear_damping, &b->sim.angular_damping, &b->sim.gravity_scale, &b->sim.center0.x, &b->sim.center0.y,
                            &b->sim.q0.c, &b->sim.q0.s, &b->sim.dq.c, &b->sim.dq.s, &b->extent, &b->min_extent,
                            &b->sleep_time, &b->island_rest};
    ga2d_real q2;
    size_t i;
    if (b->type < 0) return b->type == -1 && b->next_free >= -1 && b->next_free < body_used;
    if (b->type > GA2D_BODY_DYNAMIC || b->generation == 0) return 0;
    for (i = 0; i < sizeof r / sizeof r[0]; ++i)
        if (!ga2d__finite(*r[i])) return 0;
    if (b->mass < 0 || b->sim.inv_mass < 0 || b->inertia < 0 || b->sim.inv_inertia < 0 || b->sim.linear_damping < 0 ||
        b->sim.angular_damping < 0 || b->extent < 0 || b->min_extent < 0)
        return 0;
    q2 = b->sim.q.c * b->sim.q.c + b->sim.q.s * b->sim.q.s;
    if (!(q2 > GA2D__R(0.99) && q2 < GA2D__R(1.01))) return 0;
    if ((b->awake | b->fixed_rotation | b->sim.field_valid | b->is_bullet) & ~1) return 0;
    return 1;
}

/* A saved shape is one the library could have made: a geometry its body
   may carry, as ga2d__geometry_check leaves it (a polygon exactly as
   ga2d_polygon_make gives it), material and flags that are so.  (Free
   slots: only their link is used.) */
static int ga2d__snap_shape_ok(const ga2d_world *t, const ga2d__shape *s, int shape_used)
{
    ga2d_geometry g;
    if (s->type < 0) return s->type == -1 && s->next_free >= -1 && s->next_free < shape_used;
    if (s->type > GA2D_SHAPE_CHAIN_SEGMENT || s->generation == 0 || s->body < 0 || s->body >= t->body_used ||
        t->bodies[s->body].type < 0 || s->next < -1 || s->next >= shape_used || ((s->in_move | s->is_sensor | s->sensor_events | s->pre_solve_events | s->hit_events) & ~1))
        return 0;
    if (!ga2d__finite(s->density) || !ga2d__finite(s->friction) || !ga2d__finite(s->restitution) ||
        !ga2d__finite(s->tangent_speed) || !ga2d__finite(s->rolling_resistance) || s->rolling_resistance < 0 || s->density < 0 ||
        s->friction < 0 || s->restitution < 0)
        return 0;
    if (ga2d__geometry_check(&s->geom, t->bodies[s->body].type, s->density, &g) != GA2D_OK) return 0;
    if (s->type == GA2D_SHAPE_POLYGON) {
        const ga2d_polygon *p = &g.as.polygon, *q = &s->geom.as.polygon;
        int k;
        if (p->count != q->count) return 0;
        for (k = 0; k < p->count; ++k)
            if (memcmp(&p->vertices[k], &q->vertices[k], sizeof p->vertices[k]) != 0 ||
                memcmp(&p->normals[k], &q->normals[k], sizeof p->normals[k]) != 0)
                return 0;
    }
    return 1;
}

static int ga2d__snap_box_ok(ga2d_aabb box)
{
    return ga2d__finite(box.lower.x) && ga2d__finite(box.lower.y) && ga2d__finite(box.upper.x) &&
           ga2d__finite(box.upper.y) && box.lower.x <= box.upper.x && box.lower.y <= box.upper.y;
}

/* Reads the bodies into t (a new world): slots, the free list and the
   moving list.  0: bad snapshot, -1: out of memory. */
static int ga2d__snap_read_bodies(ga2d_world *t, ga2d__codec *k)
{
    int used = 0, free_head = 0, count = 0, i, live = 0, frees = 0;
    ga2d__io_int(k, &used);
    ga2d__io_int(k, &free_head);
    ga2d__io_int(k, &count);
    /* every slot takes at least its type, link and generation */
    if (!k->ok || used < 0 || used > GA2D__MAX_BODIES || count < 0 || count > used || free_head < -1 ||
        free_head >= used || (size_t)used > (k->n - k->at) / (2 * sizeof(int) + sizeof(uint32_t)))
        return 0;
    if (used == 0) return free_head == -1 && count == 0;
    if (!ga2d__grow(&t->mem, (void **)&t->bodies, &t->body_capacity, used, sizeof *t->bodies) ||
        !ga2d__grow(&t->mem, (void **)&t->wake_queue, &t->wake_capacity, used, sizeof *t->wake_queue) ||
        !ga2d__grow(&t->mem, (void **)&t->moving, &t->moving_capacity, used, sizeof *t->moving) ||
        !ga2d__reserve_slots(t, used))
        return -1;
    if (t->def.integrator == GA2D_INTEGRATOR_RK4 && !ga2d__reserve_rk4(t, t->moving_capacity)) return -1;
    if (!ga2d__reserve_moving(t, t->moving_capacity)) return -1;
    memset(t->bodies, 0, (size_t)used * sizeof *t->bodies);
    t->body_used = used;
    t->body_count = count;
    t->free_head = free_head;
    for (i = 0; i < used; ++i) {
        ga2d__body *b = &t->bodies[i];
        ga2d__io_body(k, b);
        if (!k->ok || !ga2d__snap_body_ok(b, used)) return 0;
        live += b->type >= 0;
    }
    if (live != count) return 0;
    /* the free list: free slots only, each once (the wake queue, a slot
       each, holds which were met) */
    memset(t->wake_queue, 0, (size_t)used * sizeof *t->wake_queue);
    for (i = free_head; i >= 0; i = t->bodies[i].next_free) {
        if (t->bodies[i].type != -1 || t->wake_queue[i] || ++frees > used - count) return 0;
        t->wake_queue[i] = 1;
    }
    if (frees != used - count) return 0;
    for (i = 0; i < used; ++i) {
        ga2d__body *b = &t->bodies[i];
        b->island = i;
        b->move_index = -1;
        b->contact_head = b->contact_tail = -1;
        b->joint_head = -1;
        if (b->type < 0) continue;
        if (b->type != GA2D_BODY_STATIC && b->awake) ga2d__moving_add(t, i);
    }
    return 1;
}

/* Each live body's shape list: its own live shapes, each once, head to
   tail, its count; and every live shape on one.  The wake queue, one
   entry per body, is free to count them meanwhile (0 on success). */
static int ga2d__snap_lists_ok(ga2d_world *t)
{
    int i, seen = 0;
    for (i = 0; i < t->body_used; ++i) {
        const ga2d__body *b = &t->bodies[i];
        int s, n = 0, last = -1;
        if (b->type < 0) continue;
        if (b->shape_head < -1 || b->shape_head >= t->shape_used || b->shape_count < 0) return 0;
        for (s = b->shape_head; s >= 0; s = t->shapes[s].next) {
            if (t->shapes[s].type < 0 || t->shapes[s].body != i || ++n > b->shape_count) return 0;
            last = s;
        }
        if (n != b->shape_count || last != b->shape_tail) return 0;
        seen += n;
    }
    return seen == t->shape_count;
}

/* Each sensor's visitors: live shapes it could see, ascending. */
static int ga2d__snap_visitors_ok(const ga2d_world *t)
{
    int i, j;
    for (i = 0; i < t->shape_used; ++i) {
        const ga2d__shape *se = &t->shapes[i];
        if (se->type < 0 || !se->is_sensor) continue;
        for (j = 0; j < se->visitor_count; ++j) {
            int v = se->visitors[j];
            const ga2d__shape *vi;
            if (v < 0 || v >= t->shape_used || (j > 0 && v <= se->visitors[j - 1])) return 0;
            vi = &t->shapes[v];
            if (vi->type < 0 || vi->is_sensor || !vi->sensor_events || vi->body == se->body) return 0;
        }
    }
    return 1;
}

/* Reads the shapes into t after its bodies: slots, the free list, the
   bodies' lists, the trees and the pair-finding queue.  0: bad snapshot,
   -1: out of memory. */
static int ga2d__snap_read_shapes(ga2d_world *t, ga2d__codec *k)
{
    int used = 0, free_head = 0, count = 0, i, live = 0, frees = 0, moves = 0, *seen;
    ga2d__io_int(k, &used);
    ga2d__io_int(k, &free_head);
    ga2d__io_int(k, &count);
    if (!k->ok || used < 0 || used > GA2D__MAX_BODIES || count < 0 || count > used || free_head < -1 ||
        free_head >= used || (size_t)used > (k->n - k->at) / (2 * sizeof(int) + sizeof(uint32_t)))
        return 0;
    if (used == 0) return free_head == -1 && count == 0 && ga2d__snap_lists_ok(t);
    if (!ga2d__grow(&t->mem, (void **)&t->shapes, &t->shape_capacity, used, sizeof *t->shapes) ||
        !ga2d__grow(&t->mem, (void **)&t->move_buf, &t->move_capacity, used, sizeof *t->move_buf))
        return -1;
    memset(t->shapes, 0, (size_t)used * sizeof *t->shapes);
    t->shape_used = used;
    t->shape_count = count;
    t->shape_free = free_head;
    for (i = 0; i < used; ++i) {
        ga2d__shape *sh = &t->shapes[i];
        ga2d__io_shape(k, sh);
        if (!k->ok || !ga2d__snap_shape_ok(t, sh, used)) return 0;
        if (sh->type >= 0) {
            ++live;
            moves += t->bodies[sh->body].type != GA2D_BODY_STATIC;
            t->hit_shapes += sh->hit_events;
        }
        if (sh->type >= 0 && sh->is_sensor) {
            int n = sh->visitor_count;
            sh->visitor_count = 0;
            if (!ga2d__grow(&t->mem, (void **)&sh->visitors, &sh->visitor_capacity, n, sizeof *sh->visitors)) return -1;
            if (n > 0) memcpy(sh->visitors, k->in + k->visitors_at, (size_t)n * sizeof *sh->visitors);
            sh->visitor_count = n;
            ++t->sensor_count;
        }
    }
    if (live != count || !ga2d__snap_lists_ok(t) || !ga2d__snap_visitors_ok(t)) return 0;
    /* the free list: free slots only, each once (the queue, a slot each,
       holds which were met) */
    seen = t->move_buf;
    memset(seen, 0, (size_t)used * sizeof *seen);
    for (i = free_head; i >= 0; i = t->shapes[i].next_free) {
        if (t->shapes[i].type != -1 || seen[i] || ++frees > used - count) return 0;
        seen[i] = 1;
    }
    if (frees != used - count) return 0;
    if (!ga2d__tree_reserve(&t->mem, &t->trees[0], count - moves) ||
        !ga2d__tree_reserve(&t->mem, &t->trees[1], moves))
        return -1;
    for (i = 0; i < used; ++i) {
        ga2d__shape *sh = &t->shapes[i];
        ga2d_aabb box;
        int queued = sh->in_move;
        sh->in_move = 0;
        sh->proxy = -1;
        if (sh->type < 0) continue;
        sh->tree = t->bodies[sh->body].type != GA2D_BODY_STATIC;
        sh->radius = ga2d__shape_radius(sh);
        ga2d__io_vec(k, &box.lower);
        ga2d__io_vec(k, &box.upper);
        if (!k->ok || !ga2d__snap_box_ok(box)) return 0;
        sh->proxy = ga2d__tree_create(ga2d__tree_of(t, sh), box, i, sh->filter.category_bits);
        t->bodies[sh->body].boxes_changed = t->box_clock;
        if (queued) ga2d__buffer_move(t, i);
    }
    return 1;
}

/* A touching contact's held manifold: finite, its rotor a unit one (what
   ga2d__reuse_manifold applies); only the manifold's points are read. */
static int ga2d__snap_held_ok(const ga2d__held *hd, int count)
{
    int k;
    ga2d_real n2 = hd->rel.q.c * hd->rel.q.c + hd->rel.q.s * hd->rel.q.s;
    if (!ga2d__transform_ok(hd->rel) || !ga2d__finite_vec(hd->normal) || !(GA2D__FABS(n2 - 1) <= GA2D__R(1e-3)))
        return 0;
    for (k = 0; k < count; ++k)
        if (!ga2d__finite_vec(hd->point[k]) || !ga2d__finite(hd->separation[k])) return 0;
    return 1;
}

/* A saved contact's manifold: finite, at most two points. */
static int ga2d__snap_manifold_ok(const ga2d_manifold *m)
{
    int k;
    if (!ga2d__finite_vec(m->normal)) return 0;
    for (k = 0; k < m->count; ++k) {
        const ga2d_manifold_point *p = &m->points[k];
        if (!ga2d__finite_vec(p->point) || !ga2d__finite_vec(p->anchor_a) || !ga2d__finite_vec(p->anchor_b) ||
            !ga2d__finite(p->separation) || !ga2d__finite(p->normal_impulse) || !ga2d__finite(p->tangent_impulse))
            return 0;
    }
    return 1;
}

/* Reads the chains into t after its shapes: each live chain's segments
   are live chain segments of its body that name it, each once, and every
   chain segment is on a live chain.  0: bad snapshot, -1: out of memory. */
/* A saved joint is one the library could have made: two live bodies,
   one dynamic; numbers finite and as create takes them; flags that are
   flags. */
static int ga2d__snap_joint_ok(const ga2d_world *t, const ga2d__joint *j)
{
    const ga2d_real *r[] = {&j->local[0].x, &j->local[0].y, &j->local[1].x, &j->local[1].y, &j->reference_angle, &j->lower,
                            &j->upper, &j->motor_speed, &j->max_motor, &j->hertz, &j->damping_ratio,
                            &j->linear_impulse.x, &j->linear_impulse.y, &j->spring_impulse, &j->motor_impulse,
                            &j->lower_impulse, &j->upper_impulse, &j->impulse, &j->length, &j->linear_hertz,
                            &j->linear_damping_ratio, &j->max_force, &j->max_torque, &j->correction, &j->offset.x,
                            &j->offset.y};
    size_t i;
    int s;
    if (j->type < 0 || j->type >= GA2D_JOINT_TYPE_COUNT || j->generation == 0 || j->serial == 0 || j->serial > t->joint_serial)
        return 0;
    for (s = 0; s < 2; ++s)
        if (j->body[s] < 0 || j->body[s] >= t->body_used || t->bodies[j->body[s]].type < 0) return 0;
    if (j->body[0] == j->body[1] ||
        (t->bodies[j->body[0]].type != GA2D_BODY_DYNAMIC && t->bodies[j->body[1]].type != GA2D_BODY_DYNAMIC))
        return 0;
    for (i = 0; i < sizeof r / sizeof r[0]; ++i)
        if (!ga2d__finite(*r[i])) return 0;
    if (!ga2d__coordinate_ok(j->local[0]) || !ga2d__coordinate_ok(j->local[1]) || !ga2d__coordinate_ok(j->offset) ||
        j->max_motor < 0 || j->hertz < 0 || j->damping_ratio < 0 || j->linear_hertz < 0 || j->linear_damping_ratio < 0 ||
        j->max_force < 0 || j->max_torque < 0 || j->correction < 0 || j->correction > 1 || j->lower_impulse < 0 ||
        j->upper_impulse < 0 || (j->enable_limit && j->lower > j->upper) ||
        (j->type == GA2D_JOINT_DISTANCE && (!(j->length > 0) || j->lower < 0 || j->lower > j->upper)))
        return 0;
    if ((j->type == GA2D_JOINT_PRISMATIC || j->type == GA2D_JOINT_WHEEL) &&
        !(GA2D__FABS(ga2d_dot(j->offset, j->offset) - 1) <= GA2D__R(1e-3)))
        return 0; /* the axis as create left it: unit */
    return !((j->collide_connected | j->enable_limit | j->enable_motor | j->enable_spring) & ~1);
}

typedef struct ga2d__serial_slot { uint64_t serial; int slot; } ga2d__serial_slot;
static int ga2d__serial_order(const void *a, const void *b)
{
    uint64_t x = ((const ga2d__serial_slot *)a)->serial, y = ((const ga2d__serial_slot *)b)->serial;
    return x < y ? -1 : x > y;
}

/* Reads the joints into t after its bodies: slots, the free list, and
   the bodies' joint lists rebuilt newest first, as creation leaves them.
   0: bad snapshot, -1: out of memory. */
static int ga2d__snap_read_joints(ga2d_world *t, ga2d__codec *k)
{
    int used = 0, free_head = 0, count = 0, i, j, live = 0, frees = 0;
    uint64_t last = 0;
    ga2d__io_int(k, &used);
    ga2d__io_int(k, &free_head);
    ga2d__io_int(k, &count);
    ga2d__io_u64(k, &t->joint_serial);
    if (!k->ok || used < 0 || used > GA2D__MAX_BODIES || count < 0 || count > used || free_head < -1 ||
        free_head >= used || (size_t)used > (k->n - k->at) / (2 * sizeof(int) + sizeof(uint32_t)))
        return 0;
    if (used > 0 && !ga2d__grow(&t->mem, (void **)&t->joints, &t->joint_capacity, used, sizeof *t->joints)) return -1;
    if (used > 0) memset(t->joints, 0, (size_t)used * sizeof *t->joints);
    t->joint_used = used;
    t->joint_count = count;
    t->joint_free = free_head;
    for (i = 0; i < used; ++i) {
        ga2d__joint *jt = &t->joints[i];
        ga2d__io_int(k, &jt->type);
        ga2d__io_int(k, &jt->next_free);
        ga2d__io_u32(k, &jt->generation);
        if (!k->ok) return 0;
        if (jt->type < 0) {
            if (jt->type != -1 || jt->next_free < -1 || jt->next_free >= used) return 0;
            ++frees;
            continue;
        }
        ga2d__io_joint(k, jt);
        if (!k->ok || !ga2d__snap_joint_ok(t, jt)) return 0;
        jt->next_free = -1;
        ++live;
    }
    if (live != count || frees != used - count) return 0;
    for (i = free_head, j = 0; i >= 0; i = t->joints[i].next_free)
        if (t->joints[i].type != -1 || ++j > frees) return 0;
    if (j != frees) return 0;
    /* the lists, oldest linked first (serials are distinct) */
    if (live > 0) {
        ga2d__serial_slot *order = (ga2d__serial_slot *)ga2d__alloc(&t->mem, (size_t)live * sizeof *order);
        if (!order) return -1;
        for (i = 0, j = 0; i < used; ++i)
            if (t->joints[i].type >= 0) {
                order[j].serial = t->joints[i].serial;
                order[j++].slot = i;
            }
        qsort(order, (size_t)live, sizeof *order, ga2d__serial_order);
        for (j = 0; j < live && (j == 0 || order[j].serial != last); ++j) {
            last = order[j].serial;
            ga2d__link_joint(t, order[j].slot, 0);
            ga2d__link_joint(t, order[j].slot, 1);
        }
        ga2d__free(&t->mem, order, (size_t)live * sizeof *order);
        if (j != live) return 0; /* two joints with one serial */
    }
    if (t->step.dt > 0) { /* the last step's substep, for the reaction getters */
        t->step.h = t->step.dt / (ga2d_real)t->def.substeps;
        t->step.inv_h = 1 / t->step.h;
    }
    return 1;
}

static int ga2d__snap_read_chains(ga2d_world *t, ga2d__codec *k)
{
    int used = 0, free_head = 0, count = 0, i, j, live = 0, frees = 0, listed = 0, segments = 0;
    ga2d__io_int(k, &used);
    ga2d__io_int(k, &free_head);
    ga2d__io_int(k, &count);
    if (!k->ok || used < 0 || used > GA2D__MAX_BODIES || count < 0 || count > used || free_head < -1 ||
        free_head >= used || (size_t)used > (k->n - k->at) / (2 * sizeof(int) + sizeof(uint32_t)))
        return 0;
    if (used > 0 && !ga2d__grow(&t->mem, (void **)&t->chains, &t->chain_capacity, used, sizeof *t->chains)) return -1;
    if (used > 0) memset(t->chains, 0, (size_t)used * sizeof *t->chains);
    t->chain_used = used;
    t->chain_count = count;
    t->chain_free = free_head;
    for (i = 0; i < used; ++i) {
        ga2d__chain *c = &t->chains[i];
        int n = 0;
        ga2d__io_int(k, &c->type);
        ga2d__io_int(k, &c->next_free);
        ga2d__io_u32(k, &c->generation);
        if (!k->ok || c->type < -1 || c->type > 0) return 0;
        if (c->type < 0) {
            if (c->next_free < -1 || c->next_free >= used) return 0;
            ++frees;
            continue;
        }
        ga2d__io_int(k, &c->body);
        ga2d__io_int(k, &n);
        if (!k->ok || c->generation == 0 || c->body < 0 || c->body >= t->body_used || t->bodies[c->body].type < 0 || n < 1 ||
            (size_t)n > (k->n - k->at) / sizeof(int))
            return 0;
        if (!(c->shapes = (int *)ga2d__alloc(&t->mem, (size_t)n * sizeof *c->shapes))) return -1;
        c->count = n;
        for (j = 0; j < n; ++j) {
            int s = -1;
            ga2d__io_int(k, &s);
            if (!k->ok || s < 0 || s >= t->shape_used || t->shapes[s].type != GA2D_SHAPE_CHAIN_SEGMENT ||
                t->shapes[s].chain != i || t->shapes[s].body != c->body)
                return 0;
            c->shapes[j] = s;
        }
        ++live;
        listed += n;
    }
    if (live != count || frees != used - count) return 0;
    for (i = free_head, j = 0; i >= 0; i = t->chains[i].next_free)
        if (t->chains[i].type != -1 || ++j > frees) return 0;
    if (j != frees) return 0;
    /* every chain segment on one chain's list, once: each names a live
       chain, no list holds a shape twice, and the lists' lengths add up
       to their number */
    for (i = 0; i < t->shape_used; ++i) {
        const ga2d__shape *sh = &t->shapes[i];
        if (sh->type != GA2D_SHAPE_CHAIN_SEGMENT) continue;
        if (sh->chain < 0 || sh->chain >= used || t->chains[sh->chain].type != 0) return 0;
        ++segments;
    }
    if (segments != listed) return 0;
    if (listed > 0) {
        int *seen = (int *)ga2d__alloc(&t->mem, (size_t)t->shape_used * sizeof *seen), twice = 0;
        if (!seen) return -1;
        memset(seen, 0, (size_t)t->shape_used * sizeof *seen);
        for (i = 0; i < used; ++i)
            for (j = 0; j < t->chains[i].count; ++j) twice |= seen[t->chains[i].shapes[j]]++;
        ga2d__free(&t->mem, seen, (size_t)t->shape_used * sizeof *seen);
        if (twice) return 0;
    }
    return 1;
}

/* Reads the contacts into t, oldest first, so that every body's list comes
   out as it was.  0: bad snapshot, -1: out of memory. */
static int ga2d__snap_read_contacts(ga2d_world *t, ga2d__codec *k)
{
    uint64_t serial = 0, last = 0;
    int count = 0, i;
    ga2d__io_u64(k, &serial);
    ga2d__io_int(k, &count);
    /* a contact takes at least its two slots, serial and flag */
    if (!k->ok || count < 0 || (size_t)count > (k->n - k->at) / (3 * sizeof(int) + sizeof(uint64_t))) return 0;
    for (i = 0; i < count; ++i) {
        ga2d__contact c;
        ga2d__contact *ct;
        memset(&c, 0, sizeof c);
        ga2d__io_contact(k, &c);
        if (!k->ok) return 0;
        if (c.shape_a < 0 || c.shape_b >= t->shape_used || c.shape_a >= c.shape_b || t->shapes[c.shape_a].type < 0 ||
            t->shapes[c.shape_b].type < 0 || !ga2d__pair_wanted(t, c.shape_a, c.shape_b))
            return 0;
        if ((i > 0 && c.serial <= last) || c.serial >= serial) return 0;
        if (c.touching != (c.manifold.count > 0)) return 0;
        if (c.touching && !ga2d__snap_held_ok(&c.held, c.manifold.count)) return 0;
        if (!ga2d__snap_manifold_ok(&c.manifold) || !ga2d__finite(c.friction) || !ga2d__finite(c.restitution) ||
            c.friction < 0 || c.restitution < 0)
            return 0;
        if (!ga2d__pairs_reserve(t)) return -1;
        if (ga2d__pairs_has(t, ga2d__pair_key(c.shape_a, c.shape_b))) return 0; /* a pair twice */
        if (!ga2d__create_contact(t, c.shape_a, c.shape_b)) return -1;
        ct = &t->contacts[t->contact_used - 1];
        ct->manifold = c.manifold;
        ct->touching = c.touching;
        t->touching_count += c.touching;
        ct->friction = c.friction;
        ct->restitution = c.restitution;
        ct->held = c.held;
        ct->serial = c.serial;
        last = c.serial;
    }
    t->contact_serial = serial;
    return 1;
}

GA2D_API ga2d_result ga2d_world_snapshot_load(ga2d_world *w, const void *buf, size_t size)
{
    ga2d__snap_header h, want;
    ga2d__codec r;
    ga2d_world_def d;
    ga2d_world *t, swap;
    int ok;
    if (!w || !buf) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    if (size < sizeof h) return GA2D_ERR_BAD_SNAPSHOT;
    memcpy(&h, buf, sizeof h);
    want = ga2d__snap_header_make(h.payload_size);
    want.checksum = h.checksum;
    if (memcmp(&h, &want, sizeof h) != 0 || h.payload_size != (uint64_t)(size - sizeof h)) return GA2D_ERR_BAD_SNAPSHOT;
    memset(&r, 0, sizeof r);
    r.in = (const unsigned char *)buf + sizeof h;
    r.n = size - sizeof h;
    r.loading = r.ok = 1;
    if (ga2d__fnv1a(r.in, r.n) != h.checksum) return GA2D_ERR_BAD_SNAPSHOT;
    /* the def, with this world's allocator and callback */
    memset(&d, 0, sizeof d);
    ga2d__io_def(&r, &d);
    if (!r.ok) return GA2D_ERR_BAD_SNAPSHOT;
    d.allocator = w->def.allocator;
    d.force_callback = w->def.force_callback;
    d.force_context = w->def.force_context;
    d.pre_solve = w->def.pre_solve;
    d.pre_solve_context = w->def.pre_solve_context;
    d.worker_count = w->def.worker_count;
    d.enqueue_task = w->def.enqueue_task;
    d.finish_task = w->def.finish_task;
    d.user_task_context = w->def.user_task_context;
    if (d.internal_cookie != GA2D_DEF_COOKIE || ga2d__world_def_check(&d) != GA2D_OK || d.substeps == 0 ||
        d.length_units_per_meter == 0)
        return GA2D_ERR_BAD_SNAPSHOT;
    /* t's allocations run the user's hooks: w is locked meanwhile */
    w->lock = GA2D__LOCK_ALLOC;
    ga2d__enter(w);
    t = ga2d_world_create(&d);
    if (!t) {
        w->lock = 0;
        ga2d__leave(w);
        return GA2D_ERR_OUT_OF_MEMORY;
    }
    ga2d__enter(t);
    ga2d__io_double(&r, &t->time);
    ga2d__io_real(&r, &t->step.dt);
    ga2d__io_counters(&r, &t->counters);
    ga2d__io_u32(&r, &t->tag);
    ok = r.ok && t->time == t->time && ga2d__finite(t->step.dt) && t->step.dt > 0;
    if (ok) ok = ga2d__snap_read_bodies(t, &r);
    if (ok == 1) ok = ga2d__snap_read_shapes(t, &r);
    if (ok == 1) ok = ga2d__snap_read_chains(t, &r);
    if (ok == 1) ok = ga2d__snap_read_joints(t, &r);
    if (ok == 1) ok = ga2d__snap_read_contacts(t, &r);
    if (ok == 1 && r.at != r.n) ok = 0;
    --t->depth;
    if (ok == 1 && !w->destroy_pending) {
        /* all checked: the new state goes into w, the old one is freed
           with t; each keeps its own hooks and bookkeeping */
        swap = *w;
        *w = *t;
        *t = swap;
        w->mem.ctx = w;
        t->mem.ctx = t;
        w->step.world = w;
        t->step.world = t;
        w->lock = t->lock;
        w->depth = t->depth;
        w->destroy_pending = 0;
        t->lock = 0;
        t->depth = 0;
    }
    ga2d_world_destroy(t); /* the rejected new state, or the old one */
    w->lock = 0;
    ga2d__leave(w);
    if (ok != 1) return ok < 0 ? GA2D_ERR_OUT_OF_MEMORY : GA2D_ERR_BAD_SNAPSHOT;
    return GA2D_OK;
}

/* ============================================================= debug draw */
GA2D_API ga2d_debug_draw ga2d_default_debug_draw(void)
{
    ga2d_debug_draw d;
    memset(&d, 0, sizeof d);
    d.draw_bodies = 1;
    d.draw_joints = 1;
    return d;
}

static void ga2d__draw(const ga2d_world *w, const ga2d_debug_draw *d);

static uint32_t ga2d__state_color(const ga2d__body *b)
{
    if (b->type == GA2D_BODY_STATIC) return GA2D_COLOR_STATIC;
    if (b->type == GA2D_BODY_KINEMATIC) return GA2D_COLOR_KINEMATIC;
    return b->awake ? GA2D_COLOR_AWAKE : GA2D_COLOR_ASLEEP;
}

/* The callbacks are user code: the world is locked while they run (it is
   const to the caller, not in memory), so nothing they call can move the
   arrays read here; a world destroyed from one goes once the draw ends. */
GA2D_API ga2d_result ga2d_world_draw(const ga2d_world *cw, const ga2d_debug_draw *d)
{
    ga2d_world *w = (ga2d_world *)cw;
    if (!w || !d) return GA2D_ERR_INVALID_ARGUMENT;
    if (w->lock) return GA2D_ERR_LOCKED;
    w->lock = GA2D__LOCK_DRAW;
    ga2d__enter(w);
    ga2d__draw(w, d);
    w->lock = 0;
    ga2d__leave(w);
    return GA2D_OK;
}

/* One shape of a body placed by x. */
static void ga2d__draw_shape(const ga2d_world *w, const ga2d_debug_draw *d, int slot, const ga2d__shape *sh, ga2d_transform x)
{
    const ga2d_geometry *g = &sh->geom;
    uint32_t color = ga2d__state_color(&w->bodies[slot]);
    switch (g->type) {
    case GA2D_SHAPE_POLYGON:
        if (d->polygon) d->polygon(ga2d__id_of(w, slot), &g->as.polygon, x, color, d->context);
        break;
    case GA2D_SHAPE_CIRCLE:
        if (d->circle)
            d->circle(ga2d__id_of(w, slot), ga2d_transform_apply(x, g->as.circle.center), g->as.circle.radius,
                      ga2d_rotate(x.q, ga2d_vec_make(1, 0)), color, d->context);
        break;
    case GA2D_SHAPE_CAPSULE:
        if (d->capsule)
            d->capsule(ga2d__id_of(w, slot), ga2d_transform_apply(x, g->as.capsule.center1),
                       ga2d_transform_apply(x, g->as.capsule.center2), g->as.capsule.radius, color, d->context);
        break;
    default:
        if (d->segment)
            d->segment(ga2d_transform_apply(x, ga2d__segment_of(g)->point1), ga2d_transform_apply(x, ga2d__segment_of(g)->point2), color,
                       d->context);
        break;
    }
}

/* Every live body in slot order, its shapes in their order, then the
   touching contacts' points.  A world destroyed from a callback gets no
   further callback: each call is made only while no destruction is
   pending. */
static void ga2d__draw(const ga2d_world *w, const ga2d_debug_draw *d)
{
    int s, ci, k, j;
    for (s = 0; s < w->body_used && !w->destroy_pending; ++s) {
        const ga2d__body *b = &w->bodies[s];
        if (b->type < 0) continue;
        for (j = b->shape_head; j >= 0 && d->draw_bodies && !w->destroy_pending; j = w->shapes[j].next)
            ga2d__draw_shape(w, d, s, &w->shapes[j], ga2d__body_xf(b));
        for (j = b->shape_head; j >= 0 && d->draw_aabbs && d->aabb && !w->destroy_pending; j = w->shapes[j].next)
            d->aabb(ga2d__fat_box(w, &w->shapes[j]), GA2D_COLOR_AABB, d->context);
        if (d->draw_centers && d->point && !w->destroy_pending)
            d->point(b->sim.center, GA2D__DRAW_CENTER_SIZE * w->def.length_units_per_meter, ga2d__state_color(b), d->context);
    }
    if (d->draw_contacts && d->contact)
        for (ci = 0; ci < w->contact_used && !w->destroy_pending; ++ci) {
            const ga2d__contact *c = &w->contacts[ci];
            if (c->next_free != -2 || !c->touching) continue;
            for (k = 0; k < c->manifold.count && !w->destroy_pending; ++k)
                d->contact(c->manifold.points[k].point, c->manifold.normal, c->manifold.points[k].separation,
                           GA2D_COLOR_CONTACT, d->context);
        }
    if (d->draw_joints && d->segment)
        for (ci = 0; ci < w->joint_used && !w->destroy_pending; ++ci) {
            const ga2d__joint *jt = &w->joints[ci];
            const ga2d__body *a, *b;
            ga2d_vec pa, pb;
            if (jt->type < 0) continue;
            a = &w->bodies[jt->body[0]];
            b = &w->bodies[jt->body[1]];
            pa = ga2d_vec_add(ga2d__body_origin(a), ga2d_rotate(a->sim.q, jt->local[0]));
            pb = ga2d_vec_add(ga2d__body_origin(b), ga2d_rotate(b->sim.q, jt->local[1]));
            d->segment(a->sim.center, pa, GA2D_COLOR_JOINT, d->context);
            if (!w->destroy_pending) d->segment(pa, pb, GA2D_COLOR_JOINT, d->context);
            if (!w->destroy_pending) d->segment(pb, b->sim.center, GA2D_COLOR_JOINT, d->context);
        }
}

#ifdef __cplusplus
}
#endif
#endif /* GA2D_IMPLEMENTATION */

/*
------------------------------------------------------------------------------
VERSION HISTORY (newest first)
------------------------------------------------------------------------------
   0.9.0  shapes: bodies of any number of circles, capsules, convex and
          rounded polygons, segments and one-sided chains, each with its
          own material, filter and user data; exact mass of each and of
          the body as their sum; manifolds for every pair (the world-free
          ga2d_collide_shapes); round shapes roll (a round anchor's radius
          does not turn with its body, and the shared point slides with
          the round side); sensors with bookended events; hit events; a
          pre-solve callback; conveyor belts and rolling resistance;
          ga2d_body_get_contacts faces out of the asked-for body; the
          default body def has no polygon (a body gets shapes, or
          def.polygon as a shortcut); makers that say why they refuse;
          snapshots version 7 (shapes, sensors' overlaps, chains); inside,
          the body in parts (its integration state apart).  Between two
          sharp sides the shared point is the incident corner, no longer
          the anchors' midpoint (a frictionless box sliding on flat ground
          kept a spurious vertical speed and spin growing as v^2), so
          polygon worlds step differently from 0.8.2 (new pinned hashes);
          box scenes step as fast as in 0.8.2.
   0.8.2  a def zero-initialised by hand is the defaults, switches
          included (its enable_* fields read 0 as off, and friction, sleep,
          warm starting and restitution vanished); the default functions
          stamp internal_cookie, so their defs keep every zero as set;
          the defaults are named constants (GA2D_DEFAULT_*) resolved in
          one function per def; snapshots written field by field
          (version 6: no padding bytes, the structs free to change); the
          |g| h^2 bound is measured scaled (it overflowed at huge length
          units);
          inside, the step reads as a list of stages over ranges of
          bodies, contacts, constraints and lane groups, its per-step state
          in one step context, and stages that compute leave creation,
          destruction, events and waking to the book-keeping after them;
          a body is in parts: its integration state (what the integrators
          take), its book-keeping and what it is made of (bit-identical
          results).
   0.8.1  hostile input: user code run from the force callback, the debug
          draw or the allocator hooks finds the world locked, and a world
          destroyed from it goes when the library call returns; fat boxes
          hold all a body can reach in the step (fast bodies passed thin
          walls every other step); a contact deeper than the speculative
          distance keeps its island awake; the incident edge is chosen to
          full precision (a thin arc rocked and sank in float); ids carry
          their world's tag; bounds on coordinates, the step and gravity
          (TOO_LARGE); counters.speed_caps; ga2d_world_compact; the margin
          of a small body's fat box scales with it; lane groups grow as
          they open (a pile of 0.2 m boxes: 5.5 KB a body, from 9.6);
          snapshot version 4;
          the re-entry fuzz harness's findings: restitution writes no
          static body (a blown-up body made the ground NaN), the force
          field never reads a non-finite state, RK4's displacement keeps
          the speed caps, the error body is the lowest slot contained.
   0.8.0  a touching pair that moved by under half a slop keeps its
          manifold, carried along with the bodies (no separating-axis
          search); solver bodies load into the lanes as whole rows; the
          hull is wrapped as monotone chains (a cloud whose features were
          near the tolerance could leave a point outside); snapshot
          version 3; counters.manifolds_carried; the lane groups'
          impulses go straight back to the manifolds.
   0.7.0  a manifold's two normal points are solved together (a 2x2
          complementarity block) instead of one after the other: stacks
          no longer lean the way the points are ordered.
   0.6.0  the velocity passes run on groups of constraints with no moved
          body in common, a SIMD lane each (4 floats or 2 doubles; 8 or 4
          under AVX), in the same Gauss-Seidel order and with the same bits
          as one constraint at a time; snapshot version 2.
   0.5.0  determinism (canonical solver order, same bits across compilers,
          -O levels and C/C++), world snapshots for rollback, containment
          of bodies driven non-finite (ga2d_world_error_body); bounces at
          the defaults reach e^(2n) h0.
   0.4.0  contact solver: soft step, PGS + Baumgarte, PGS + NGS; friction;
          restitution as a collision phase; warm starting; sleep.
   0.3.0  SAT narrowphase, dynamic AABB tree broadphase, contacts, events,
          filtering.
   0.2.0  world and bodies; symplectic Euler, Verlet and RK4 integrators;
          exact and first-order rotor updates; force callback; counters.
   0.1.0  algebra, polygons, hull, exact mass properties.
*/

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
