/* Documented features that no other test would miss if they broke (issue
   23, finding 9): sensors, waking by every setter and push, the sleep
   switch, conveyor belts at steady state, filters in a world, chain
   segments, the world's switch setters, the shape setters and getters,
   and the public functions no other test calls.  `make mutate` plants a
   bug in each (tests/mutate/mutants.txt) and requires the suite to fail. */
#include "test.h"

#define DT (1.0 / 60)
#define G 10.0
#define SLOP GA2D_LINEAR_SLOP

static int verbose(void)
{
    const char *v = getenv("GA2D_TEST_VERBOSE");
    return v != NULL && v[0] != '\0';
}

static ga2d_vec v2(double x, double y) { return ga2d_vec_make((ga2d_real)x, (ga2d_real)y); }

static ga2d_body_id static_box(ga2d_world *w, double x, double y, double hw, double hh)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.position = v2(x, y);
    d.polygon = ga2d_polygon_box((ga2d_real)hw, (ga2d_real)hh);
    return ga2d_body_create(w, &d);
}

static ga2d_body_id dynamic_body(ga2d_world *w, double x, double y)
{
    ga2d_body_def d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = v2(x, y);
    return ga2d_body_create(w, &d);
}

static ga2d_shape_id add_box(ga2d_world *w, ga2d_body_id b, const ga2d_shape_def *sd, double hw, double hh)
{
    ga2d_polygon p = ga2d_polygon_box((ga2d_real)hw, (ga2d_real)hh);
    return ga2d_shape_create_polygon(w, b, sd, &p);
}

static ga2d_shape_id add_circle(ga2d_world *w, ga2d_body_id b, const ga2d_shape_def *sd, double r)
{
    ga2d_circle c;
    c.center = v2(0, 0);
    c.radius = (ga2d_real)r;
    return ga2d_shape_create_circle(w, b, sd, &c);
}

/* ============================================================ sensors */
/* Bodies fall from rest through a static sensor box |x| <= 3, |y| <= 1,
   with no ground.  Symplectic Euler from rest: after n substeps of h,
   v_n = -g h n and y_n = y0 - g h^2 n (n + 1) / 2.  A sensor never pushes,
   so every body keeps to that fall, to rounding: each substep rounds v
   (<= u |v|) and y (<= u (|y| + |v| h)), and an error in v carries into
   y for the remaining substeps, so |y - y_n| <= n u (|y|max + 2 n |v|max h).
   At the end of step s (n = 4 s) a body whose lowest point (y less its
   extent e below the centre) is at or under the top y = 1 and whose top
   (y + e) is at or over the bottom y = -1 overlaps the zone (touching
   counts): the step the lowest point first reaches 1 has the begin event,
   the step the top first passes -1 the end, and the zone lists it as a
   visitor in between; a margin of 1 mm from those planes at every step
   (checked: the premise) keeps rounding out of the prediction.  Three
   shapes (circle, box, capsule) from three heights; a circle with
   enable_sensor_events = 0 and a body carrying a sensor circle of its own
   (sensors do not see sensors) fall too and are never seen, and that
   sensor adds no mass to its body. */
#define FALLERS 5
static void sensor_free_fall(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id zone_body, body[FALLERS];
    ga2d_shape_id zone, seen[FALLERS], extra_sensor;
    const double xs[FALLERS] = {-2.4, -1.2, 0, 1.2, 2.4}, y0[FALLERS] = {2.0, 2.6, 3.1, 2.3, 2.8};
    const double ext[FALLERS] = {0.25, 0.3, 0.1, 0.25, 0.25}; /* extent below and above the centre */
    const int visible[FALLERS] = {1, 1, 1, 0, 0};
    const double h = DT / 4, u = REAL_EPS / 2, margin = 1e-3;
    int begin_step[FALLERS], end_step[FALLERS], got_begin[FALLERS], got_end[FALLERS];
    int i, s, bad_event = 0, bad_list = 0, premise = 1;
    double worst = 0, bound;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    {
        ga2d_body_def d = ga2d_default_body_def();
        zone_body = ga2d_body_create(w, &d); /* static, shapeless */
    }
    sd.is_sensor = 1;
    zone = add_box(w, zone_body, &sd, 3, 1);
    CHECK(!ga2d_shape_id_is_null(zone));
    sd.is_sensor = 0;
    for (i = 0; i < FALLERS; ++i) {
        body[i] = dynamic_body(w, xs[i], y0[i]);
        sd.enable_sensor_events = i < 3; /* the last two: never seen */
        if (i == 0 || i >= 3) seen[i] = add_circle(w, body[i], &sd, ext[i]);
        else if (i == 1) seen[i] = add_box(w, body[i], &sd, 0.2, ext[i]);
        else {
            ga2d_capsule c;
            c.center1 = v2(-0.2, 0);
            c.center2 = v2(0.2, 0);
            c.radius = (ga2d_real)ext[i];
            seen[i] = ga2d_shape_create_capsule(w, body[i], &sd, &c);
        }
        CHECK(!ga2d_shape_id_is_null(seen[i]));
    }
    sd.enable_sensor_events = 1;
    {
        /* the last faller also carries a sensor circle of radius 0.4: it
           reaches no other faller (1.2 m apart) and adds no mass */
        ga2d_mass before = ga2d_body_mass_data(w, body[4]), after;
        sd.is_sensor = 1;
        extra_sensor = add_circle(w, body[4], &sd, 0.4);
        CHECK(!ga2d_shape_id_is_null(extra_sensor));
        after = ga2d_body_mass_data(w, body[4]);
        CHECK(after.mass == before.mass && after.inertia == before.inertia);
    }
    /* the predicted begin and end steps */
    for (i = 0; i < FALLERS; ++i) {
        begin_step[i] = end_step[i] = -1;
        got_begin[i] = got_end[i] = -1;
        for (s = 1; s <= 90; ++s) {
            double n = 4.0 * s, y = y0[i] - G * h * h * n * (n + 1) / 2;
            if (fabs(y - ext[i] - 1) < margin || fabs(y + ext[i] + 1) < margin) premise = 0;
            if (begin_step[i] < 0 && y - ext[i] <= 1) begin_step[i] = s;
            if (end_step[i] < 0 && y + ext[i] < -1) end_step[i] = s;
        }
        CHECK(begin_step[i] > 1 && end_step[i] > begin_step[i]);
    }
    CHECK(premise);
    /* n <= 360 substeps, |y| <= 10 m, |v| <= g 1.5 s */
    bound = 360 * u * (10 + 2 * 360 * (G * 90 * DT) * h);
    for (s = 1; s <= 90; ++s) {
        ga2d_sensor_events ev;
        ga2d_shape_id list[FALLERS + 2];
        int k, expect_list = 0, n_list;
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
        ev = ga2d_world_sensor_events(w);
        for (k = 0; k < ev.begin_count + ev.end_count; ++k) {
            const ga2d_sensor_event *e = k < ev.begin_count ? &ev.begin[k] : &ev.end[k - ev.begin_count];
            int which = -1;
            for (i = 0; i < FALLERS; ++i)
                if (ga2d_shape_id_equal(e->visitor, seen[i])) which = i;
            if (!ga2d_shape_id_equal(e->sensor, zone) || which < 0 || !visible[which]) {
                ++bad_event;
                continue;
            }
            if (k < ev.begin_count) got_begin[which] = got_begin[which] < 0 ? s : 1000;
            else got_end[which] = got_end[which] < 0 ? s : 1000;
        }
        n_list = ga2d_shape_get_sensor_overlaps(w, zone, list, FALLERS + 2);
        for (i = 0; i < FALLERS; ++i) {
            double n = 4.0 * s, y = y0[i] - G * h * h * n * (n + 1) / 2;
            ga2d_vec c = ga2d_body_center(w, body[i]);
            int inside = visible[i] && s >= begin_step[i] && s < end_step[i], listed = 0;
            if (fabs((double)c.y - y) > worst) worst = fabs((double)c.y - y);
            CHECK(c.x == (ga2d_real)xs[i]);
            for (k = 0; k < n_list && k < FALLERS + 2; ++k) listed += ga2d_shape_id_equal(list[k], seen[i]);
            expect_list += inside;
            if (listed != inside) ++bad_list;
        }
        if (n_list != expect_list) ++bad_list;
        CHECK(ga2d_shape_get_sensor_overlaps(w, extra_sensor, NULL, 0) == 0);
    }
    CHECK(bad_event == 0);
    CHECK(bad_list == 0);
    CHECK(worst <= bound);
    for (i = 0; i < FALLERS; ++i) {
        if (visible[i]) {
            CHECK(got_begin[i] == begin_step[i]);
            CHECK(got_end[i] == end_step[i]);
        } else {
            CHECK(got_begin[i] < 0 && got_end[i] < 0);
        }
    }
    if (verbose())
        printf("  features: sensor: begins at steps %d %d %d, ends %d %d %d (as predicted: %d); fall error %.3g m "
               "(bound %.3g)\n",
               got_begin[0], got_begin[1], got_begin[2], got_end[0], got_end[1], got_end[2],
               got_begin[0] == begin_step[0] && got_end[2] == end_step[2], worst, bound);
    ga2d_world_destroy(w);
}

/* ============================================================ waking */
/* Two boxes stacked on a static ground fall asleep together (one island:
   they touch).  Each setter and each push of the README's "A touch, a
   force, an impulse or a setter wakes the island" is then called on the
   top box, with values that change nothing else, and both boxes must be
   awake at once (before any step): the body, and through their touching
   contact, its island. */
enum { WAKE_SET_AWAKE, WAKE_TRANSFORM, WAKE_VELOCITY, WAKE_ANGULAR_VELOCITY, WAKE_MASS_DATA, WAKE_GRAVITY_SCALE,
       WAKE_BODY_FILTER, WAKE_SHAPE_FILTER, WAKE_SHAPE_FRICTION, WAKE_FORCE, WAKE_FORCE_TO_CENTER, WAKE_TORQUE, WAKE_IMPULSE,
       WAKE_ANGULAR_IMPULSE, WAKE_KINDS };
static const char *const wake_names[WAKE_KINDS] = {"set_awake", "set_transform", "set_velocity", "set_angular_velocity",
                                                   "set_mass_data", "set_gravity_scale", "body set_filter",
                                                   "shape set_filter", "shape set_friction", "apply_force", "apply_force_to_center",
                                                   "apply_torque", "apply_impulse", "apply_angular_impulse"};

static ga2d_result wake_by(ga2d_world *w, ga2d_body_id b, int kind)
{
    ga2d_vec c = ga2d_body_center(w, b);
    ga2d_shape_id sh;
    switch (kind) {
    case WAKE_SET_AWAKE: return ga2d_body_set_awake(w, b, 1);
    case WAKE_TRANSFORM: return ga2d_body_set_transform(w, b, ga2d_body_position(w, b), ga2d_body_rotor(w, b));
    case WAKE_VELOCITY: return ga2d_body_set_velocity(w, b, v2(0.01, 0));
    case WAKE_ANGULAR_VELOCITY: return ga2d_body_set_angular_velocity(w, b, (ga2d_real)0.01);
    case WAKE_MASS_DATA: return ga2d_body_set_mass_data(w, b, ga2d_body_mass_data(w, b));
    case WAKE_GRAVITY_SCALE: return ga2d_body_set_gravity_scale(w, b, 1);
    case WAKE_BODY_FILTER: return ga2d_body_set_filter(w, b, ga2d_default_filter());
    case WAKE_SHAPE_FILTER:
        if (ga2d_body_get_shapes(w, b, &sh, 1) != 1) return GA2D_ERR_INVALID_ARGUMENT;
        return ga2d_shape_set_filter(w, sh, ga2d_default_filter());
    case WAKE_SHAPE_FRICTION:
        if (ga2d_body_get_shapes(w, b, &sh, 1) != 1) return GA2D_ERR_INVALID_ARGUMENT;
        return ga2d_shape_set_friction(w, sh, (ga2d_real)0.1);
    case WAKE_FORCE: return ga2d_body_apply_force(w, b, v2(0, 1), c);
    case WAKE_FORCE_TO_CENTER: return ga2d_body_apply_force_to_center(w, b, v2(0, 1));
    case WAKE_TORQUE: return ga2d_body_apply_torque(w, b, (ga2d_real)0.01);
    case WAKE_IMPULSE: return ga2d_body_apply_impulse(w, b, v2(0, 0.01), c);
    case WAKE_ANGULAR_IMPULSE: return ga2d_body_apply_angular_impulse(w, b, (ga2d_real)0.001);
    default: return GA2D_ERR_INVALID_ARGUMENT;
    }
}

/* Two boxes stacked on a static ground, asleep together; NULL world if
   they never slept (a failed premise, reported). */
static ga2d_world *sleeping_pair(ga2d_body_id *lower, ga2d_body_id *upper)
{
    ga2d_world *w = ga2d_world_create(NULL);
    ga2d_body_def d = ga2d_default_body_def();
    int i, slept = -1;
    CHECK(w != NULL);
    if (!w) return NULL;
    CHECK(!ga2d_body_id_is_null(static_box(w, 0, -0.5, 5, 0.5)));
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    d.position = v2(0, 0.5);
    *lower = ga2d_body_create(w, &d);
    d.position = v2(0, 1.5);
    *upper = ga2d_body_create(w, &d);
    /* at rest from the start: asleep after the 0.5 s rest time, well
       within 3 s (the premise) */
    for (i = 0; i < 180 && slept < 0; ++i) {
        CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
        if (!ga2d_body_is_awake(w, *lower) && !ga2d_body_is_awake(w, *upper)) slept = i;
    }
    CHECK(slept >= 0);
    if (slept < 0) {
        ga2d_world_destroy(w);
        return NULL;
    }
    return w;
}

static void every_setter_and_push_wakes_the_island(void)
{
    int kind;
    for (kind = 0; kind < WAKE_KINDS; ++kind) {
        ga2d_body_id lower, upper;
        ga2d_world *w = sleeping_pair(&lower, &upper);
        if (!w) return;
        CHECK_RESULT(wake_by(w, upper, kind), GA2D_OK);
        if (!ga2d_body_is_awake(w, upper) || !ga2d_body_is_awake(w, lower))
            test_fail(__FILE__, __LINE__, "%s left the %s asleep", wake_names[kind],
                      ga2d_body_is_awake(w, upper) ? "rest of the island" : "body");
        ga2d_world_destroy(w);
    }
}

/* Making a joint wakes both its bodies: a hinge put on a sleeping stack
   must act at once (the README's joints section). */
static void making_a_joint_wakes_its_bodies(void)
{
    ga2d_body_id lower, upper;
    ga2d_world *w = sleeping_pair(&lower, &upper);
    ga2d_revolute_joint_def d = ga2d_default_revolute_joint_def();
    if (!w) return;
    d.body_a = lower;
    d.body_b = upper;
    d.local_anchor_a = v2(0, 0.5);
    d.local_anchor_b = v2(0, -0.5);
    CHECK(!ga2d_joint_id_is_null(ga2d_revolute_joint_create(w, &d)));
    CHECK(ga2d_body_is_awake(w, lower) && ga2d_body_is_awake(w, upper));
    ga2d_world_destroy(w);
}

/* The README's other half: damping, restitution and user data change
   nothing for a body at rest, and leave its island asleep (waking it would
   cost a game its sleeping piles each time it tags a body). */
static void setters_that_change_nothing_at_rest_leave_it_asleep(void)
{
    int kind;
    for (kind = 0; kind < 3; ++kind) {
        static const char *const names[3] = {"set_damping", "shape set_restitution", "set_user_data"};
        ga2d_body_id lower, upper;
        ga2d_shape_id sh;
        ga2d_world *w = sleeping_pair(&lower, &upper);
        if (!w) return;
        CHECK(ga2d_body_get_shapes(w, upper, &sh, 1) == 1);
        if (kind == 0) CHECK_RESULT(ga2d_body_set_damping(w, upper, (ga2d_real)0.5, (ga2d_real)0.5), GA2D_OK);
        if (kind == 1) CHECK_RESULT(ga2d_shape_set_restitution(w, sh, (ga2d_real)0.5), GA2D_OK);
        if (kind == 2) CHECK_RESULT(ga2d_body_set_user_data(w, upper, &lower), GA2D_OK);
        if (ga2d_body_is_awake(w, upper) || ga2d_body_is_awake(w, lower))
            test_fail(__FILE__, __LINE__, "%s woke a body at rest", names[kind]);
        ga2d_world_destroy(w);
    }
}

/* ============================================================ sleep switch */
/* A box resting on the ground sleeps after 0.5 s of rest with sleep on;
   with enable_sleep = 0 in the def it is awake after 3 s (six rest
   times), and switching sleep off with ga2d_world_enable_sleep wakes a
   sleeping one and keeps it awake; switching it on again lets it sleep.
   Awake, the box is judged at rest by its motion: after 3 s its speed is
   under the sleep threshold (5 cm/s) it would have slept at. */
static void sleep_switch(void)
{
    int how;
    for (how = 0; how < 2; ++how) {
        ga2d_world_def wd = ga2d_default_world_def();
        ga2d_world *w;
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_body_id box;
        int i, asleep_once = 0, asleep_after = 0;
        wd.enable_sleep = how == 0 ? 0 : 1;
        w = ga2d_world_create(&wd);
        CHECK(w != NULL);
        if (!w) return;
        CHECK(!ga2d_body_id_is_null(static_box(w, 0, -0.5, 5, 0.5)));
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        d.position = v2(0, 0.5);
        box = ga2d_body_create(w, &d);
        for (i = 0; i < 180; ++i) {
            CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
            asleep_once |= !ga2d_body_is_awake(w, box);
        }
        if (how == 0) {
            CHECK(!asleep_once); /* never slept with sleep off */
            CHECK((double)ga2d_vec_length(ga2d_body_velocity(w, box)) < 0.05);
        } else {
            CHECK(asleep_once && !ga2d_body_is_awake(w, box)); /* the premise: it sleeps with sleep on */
            CHECK_RESULT(ga2d_world_enable_sleep(w, 0), GA2D_OK);
            CHECK(ga2d_body_is_awake(w, box)); /* switching off wakes the sleepers */
            for (i = 0; i < 180; ++i) {
                CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
                asleep_after |= !ga2d_body_is_awake(w, box);
            }
            CHECK(!asleep_after);
            CHECK_RESULT(ga2d_world_enable_sleep(w, 1), GA2D_OK);
            for (i = 0; i < 60; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
            CHECK(!ga2d_body_is_awake(w, box)); /* 1 s > the 0.5 s rest time */
        }
        ga2d_world_destroy(w);
    }
}

/* ============================================================ conveyor */
/* A box on a belt, at steady state.  A belt's surface moves clockwise
   round its outline at its tangent speed s: a ground's top to +x, a box's
   own bottom to -x.  Friction (mu 0.6) drives the sliding between the
   surfaces to zero, so the box ends at v_x = +s in both cases: carried by
   a belt ground, or walking on a still ground with its own belt.  It
   slips at mu g = 6 m/s^2, so it reaches |s| <= 4 within 0.67 s; then
   static friction holds it: no force acts along the belt (a force would
   accelerate it), and each substep's friction solve aims the sliding at
   zero.  What the slip's end leaves (the soft contact's own settling,
   through the box's tilt) decays with the contact's slow mode,
   omega / (2 zeta) = 2 pi 45 / 20 = 14 /s: from 4 s on, e^-46 of it, far
   under rounding.  What remains is rounding: the relax pass adds some 8
   terms to v_x per substep, each rounded at u (|v| + g h), and the next
   substep solves that away again: |v_x - s| <= 16 u (|s| + g h), not
   growing; checked over 4 s to 5 s. */
static void conveyor_steady_state(void)
{
    static const double speeds[5] = {-3, -1, 0.5, 2, 4};
    int k, on_box;
    for (on_box = 0; on_box < 2; ++on_box)
        for (k = 0; k < 5; ++k) {
            ga2d_world_def wd = ga2d_default_world_def();
            ga2d_world *w;
            ga2d_shape_def sd = ga2d_default_shape_def();
            ga2d_body_id ground, box;
            const double s = speeds[k], u = REAL_EPS / 2, h = DT / 4;
            const double bound = 16 * u * (fabs(s) + G * h);
            double worst = 0;
            int i;
            wd.enable_sleep = 0;
            w = ga2d_world_create(&wd);
            CHECK(w != NULL);
            if (!w) return;
            {
                ga2d_body_def d = ga2d_default_body_def();
                d.position = v2(0, -0.5);
                ground = ga2d_body_create(w, &d);
            }
            sd.tangent_speed = on_box ? 0 : (ga2d_real)s;
            CHECK(!ga2d_shape_id_is_null(add_box(w, ground, &sd, 100, 0.5)));
            box = dynamic_body(w, 0, 0.5);
            sd.tangent_speed = on_box ? (ga2d_real)s : 0;
            CHECK(!ga2d_shape_id_is_null(add_box(w, box, &sd, 0.5, 0.5)));
            for (i = 0; i < 300; ++i) {
                CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
                if (i >= 240) {
                    double dv = fabs((double)ga2d_body_velocity(w, box).x - s);
                    if (dv > worst) worst = dv;
                }
            }
            CHECK(worst <= bound);
            if (verbose())
                printf("  features: belt %s s = %4.1f: |v_x - s| <= %.3g m/s (bound %.3g)\n", on_box ? "on the box, " : "on the ground,",
                       s, worst, bound);
            ga2d_world_destroy(w);
        }
}

/* ============================================================ filters */
/* Box A rests on the ground; box B is dropped onto it from 0.5 m.  Where
   the filters allow the pair, B comes to rest on A (centre at y = 1.5);
   where they do not, B passes through A and rests on the ground beside it
   (y = 0.5).  The two answers are 1 m apart; a resting contact sinks under
   one slop each, so 4 slops tell them apart with room.  Categories: ground
   1, A 2, B 4; every mask holds the ground's bit.  Cases: both masks all
   (collide); A's mask without B (no); B's mask without A (no: each side's
   mask must hold the other); one negative group, masks all (no); one
   positive group, masks excluding each other (collide: the group wins);
   two different negative groups (collide: groups only act when equal).
   Then, with B resting on A, ga2d_shape_set_filter on B to a filter that
   excludes A: B falls through to the ground, and ga2d_shape_filter gives
   back what was set. */
static ga2d_filter filt(uint32_t category, uint32_t mask, int32_t group)
{
    ga2d_filter f;
    f.category_bits = category;
    f.mask_bits = mask;
    f.group_index = group;
    return f;
}

static double drop_b_on_a(ga2d_filter fa, ga2d_filter fb, int refilter_b, ga2d_filter later)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id a, b;
    ga2d_shape_id sb;
    double y;
    int i;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    if (!w) return -1;
    static_box(w, 0, -0.5, 5, 0.5);
    a = dynamic_body(w, 0, 0.5);
    sd.filter = fa;
    add_box(w, a, &sd, 0.5, 0.5);
    b = dynamic_body(w, 0, 2);
    sd.filter = fb;
    sb = add_box(w, b, &sd, 0.5, 0.5);
    for (i = 0; i < 120; ++i) ga2d_world_step(w, (ga2d_real)DT);
    if (refilter_b) {
        ga2d_filter got;
        CHECK_RESULT(ga2d_shape_set_filter(w, sb, later), GA2D_OK);
        got = ga2d_shape_filter(w, sb);
        CHECK(got.category_bits == later.category_bits && got.mask_bits == later.mask_bits &&
              got.group_index == later.group_index);
        for (i = 0; i < 120; ++i) ga2d_world_step(w, (ga2d_real)DT);
    }
    y = (double)ga2d_body_center(w, b).y;
    ga2d_world_destroy(w);
    return y;
}

static void filters_in_a_world(void)
{
    const uint32_t all = 0xFFFFFFFFu;
    struct {
        ga2d_filter a, b;
        int collide;
    } cases[6];
    int k;
    cases[0].a = filt(2, all, 0), cases[0].b = filt(4, all, 0), cases[0].collide = 1;
    cases[1].a = filt(2, all & ~4u, 0), cases[1].b = filt(4, all, 0), cases[1].collide = 0;
    cases[2].a = filt(2, all, 0), cases[2].b = filt(4, all & ~2u, 0), cases[2].collide = 0;
    cases[3].a = filt(2, all, -3), cases[3].b = filt(4, all, -3), cases[3].collide = 0;
    cases[4].a = filt(2, all & ~4u, 3), cases[4].b = filt(4, all & ~2u, 3), cases[4].collide = 1;
    cases[5].a = filt(2, all, -3), cases[5].b = filt(4, all, -5), cases[5].collide = 1;
    for (k = 0; k < 6; ++k) {
        double y = drop_b_on_a(cases[k].a, cases[k].b, 0, cases[k].b);
        CHECK(ga2d_should_collide(cases[k].a, cases[k].b) == cases[k].collide);
        CHECK(ga2d_should_collide(cases[k].b, cases[k].a) == cases[k].collide);
        if (fabs(y - (cases[k].collide ? 1.5 : 0.5)) > 4 * SLOP)
            test_fail(__FILE__, __LINE__, "filter case %d: B rests at y = %.4f, expected %.1f", k, y, cases[k].collide ? 1.5 : 0.5);
    }
    /* refiltered while resting on A: falls through */
    CHECK_NEAR(drop_b_on_a(cases[0].a, cases[0].b, 1, filt(4, all & ~2u, 0)), 0.5, 4 * SLOP);
    CHECK_NEAR(drop_b_on_a(cases[0].a, cases[0].b, 1, filt(4, all, -7)), 1.5, 4 * SLOP); /* no group in A: still collides */
}

/* The broadphase skips subtrees none of whose categories a shape's mask
   lets in.  Two things it must not skip:
   - a positive group collides its shapes whatever their categories: boxes
     of category 0 and mask 0 in group 3, one static, one dropped from
     0.5 m above it, rest stacked (centre y = 1.5), and in group 0 the
     dropped one falls past it (below y = 0 after 1 s: free fall from 2 m
     reaches -2.9 m);
   - a shape refiltered to a category another's mask lets in is seen by
     that shape's later searches: a ground of category 2 under a ball
     whose mask lacks 2, refiltered to category 4 while the ball is 10 m
     above it (its own search then finds nothing near), must catch the
     ball (rest at y = 0.5 + 0.25 within 4 slops: a resting contact sinks
     under one), by the shape's setter and by the body's. */
static double rest_on_static(ga2d_filter fs, ga2d_filter fd)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id a, b;
    double y;
    int i;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    if (!w) return -1;
    bd.position = v2(0, 0.5);
    a = ga2d_body_create(w, &bd);
    sd.filter = fs;
    add_box(w, a, &sd, 0.5, 0.5);
    b = dynamic_body(w, 0, 2);
    sd.filter = fd;
    add_box(w, b, &sd, 0.5, 0.5);
    for (i = 0; i < 60; ++i) ga2d_world_step(w, (ga2d_real)DT);
    y = (double)ga2d_body_center(w, b).y;
    ga2d_world_destroy(w);
    return y;
}

static double ball_on_refiltered_ground(int by_body)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_def bd = ga2d_default_body_def();
    ga2d_body_id g, b;
    ga2d_shape_id gs;
    double y;
    int i;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    if (!w) return -1;
    bd.position = v2(0, 0);
    g = ga2d_body_create(w, &bd);
    sd.filter = filt(2, 0xFFFFFFFFu, 0);
    gs = add_box(w, g, &sd, 5, 0.5);
    b = dynamic_body(w, 0, 10.75);
    sd.filter = filt(1, 0xFFFFFFFFu & ~2u, 0);
    add_circle(w, b, &sd, 0.25);
    ga2d_world_step(w, (ga2d_real)DT);
    if (by_body) CHECK_RESULT(ga2d_body_set_filter(w, g, filt(4, 0xFFFFFFFFu, 0)), GA2D_OK);
    else CHECK_RESULT(ga2d_shape_set_filter(w, gs, filt(4, 0xFFFFFFFFu, 0)), GA2D_OK);
    for (i = 0; i < 180; ++i) ga2d_world_step(w, (ga2d_real)DT);
    y = (double)ga2d_body_center(w, b).y;
    ga2d_world_destroy(w);
    return y;
}

static void filters_prune_the_search(void)
{
    CHECK_NEAR(rest_on_static(filt(0, 0, 3), filt(0, 0, 3)), 1.5, 4 * SLOP);
    CHECK(rest_on_static(filt(0, 0, 0), filt(0, 0, 0)) < 0);
    CHECK_NEAR(ball_on_refiltered_ground(0), 0.75, 4 * SLOP);
    CHECK_NEAR(ball_on_refiltered_ground(1), 0.75, 4 * SLOP);
}

/* ============================================================ switches */
/* A small scene that uses warm starting, friction, restitution and the
   solver kind: two boxes stacked off-centre, the top one pushed sideways,
   and a bouncy ball dropped beside them (5 m/s at impact: over the 1 m/s
   restitution threshold).  Each world switch and the solver kind set by
   its setter right after creation must step the scene bit for bit as the
   same setting in the def does, and differently from the default (the
   premise that the setting matters here). */
#define SCENE_BODIES 3
typedef struct scene_state { double s[SCENE_BODIES][5]; } scene_state;

static void run_scene(ga2d_world *w, scene_state *out)
{
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id b[SCENE_BODIES];
    int i, k;
    memset(out, 0, sizeof *out);
    if (!w) return;
    static_box(w, 0, -0.5, 10, 0.5);
    b[0] = dynamic_body(w, 0, 0.5);
    add_box(w, b[0], &sd, 0.5, 0.5);
    b[1] = dynamic_body(w, 0.3, 1.5);
    add_box(w, b[1], &sd, 0.5, 0.5);
    ga2d_body_set_velocity(w, b[1], v2(1, 0));
    b[2] = dynamic_body(w, 3, 1.5);
    sd.restitution = (ga2d_real)0.6;
    add_circle(w, b[2], &sd, 0.25);
    for (i = 0; i < 90; ++i) ga2d_world_step(w, (ga2d_real)DT);
    for (k = 0; k < SCENE_BODIES; ++k) {
        ga2d_vec c = ga2d_body_center(w, b[k]), v = ga2d_body_velocity(w, b[k]);
        out->s[k][0] = (double)c.x;
        out->s[k][1] = (double)c.y;
        out->s[k][2] = (double)v.x;
        out->s[k][3] = (double)v.y;
        out->s[k][4] = (double)ga2d_body_angular_velocity(w, b[k]);
    }
}

enum { SW_WARM, SW_FRICTION, SW_RESTITUTION, SW_NGS, SW_BAUMGARTE, SW_KINDS };
static void world_switch_setters(void)
{
    static const char *const names[SW_KINDS] = {"warm starting off", "friction off", "restitution off",
                                                "solver PGS_NGS", "solver PGS_BAUMGARTE"};
    scene_state ref, by_def, by_setter;
    int kind;
    {
        ga2d_world *w = ga2d_world_create(NULL);
        run_scene(w, &ref);
        if (w) ga2d_world_destroy(w);
    }
    for (kind = 0; kind < SW_KINDS; ++kind) {
        ga2d_world_def wd = ga2d_default_world_def();
        ga2d_world *w;
        ga2d_result r = GA2D_ERR_INVALID_ARGUMENT;
        if (kind == SW_WARM) wd.enable_warm_starting = 0;
        if (kind == SW_FRICTION) wd.enable_friction = 0;
        if (kind == SW_RESTITUTION) wd.enable_restitution = 0;
        if (kind == SW_NGS) wd.solver = GA2D_SOLVER_PGS_NGS;
        if (kind == SW_BAUMGARTE) wd.solver = GA2D_SOLVER_PGS_BAUMGARTE;
        w = ga2d_world_create(&wd);
        CHECK(w != NULL);
        run_scene(w, &by_def);
        if (w) ga2d_world_destroy(w);
        w = ga2d_world_create(NULL);
        CHECK(w != NULL);
        if (!w) return;
        if (kind == SW_WARM) r = ga2d_world_enable_warm_starting(w, 0);
        if (kind == SW_FRICTION) r = ga2d_world_enable_friction(w, 0);
        if (kind == SW_RESTITUTION) r = ga2d_world_enable_restitution(w, 0);
        if (kind == SW_NGS) r = ga2d_world_set_solver(w, GA2D_SOLVER_PGS_NGS);
        if (kind == SW_BAUMGARTE) r = ga2d_world_set_solver(w, GA2D_SOLVER_PGS_BAUMGARTE);
        CHECK_RESULT(r, GA2D_OK);
        run_scene(w, &by_setter);
        ga2d_world_destroy(w);
        if (memcmp(&by_def, &by_setter, sizeof by_def) != 0)
            test_fail(__FILE__, __LINE__, "%s by its setter steps differently from the def", names[kind]);
        if (memcmp(&by_def, &ref, sizeof ref) == 0) test_fail(__FILE__, __LINE__, "%s changes nothing in the scene", names[kind]);
    }
}

/* The shape setters: a box falls toward the ground with 2 m/s sideways and
   lands at 3 m/s (bouncing: restitution over the threshold, then sliding
   under friction).  Once its contact with the ground exists and before it
   touches (the premise), its friction is set to 0.1 and restitution to
   0.5: the live contact must take them (they mix at once, README), so the
   landing must go bit for bit as for a box made with 0.1 and 0.5, and
   differ from one left at 0.6 and 0.  The user data and filter getters
   give back what was set. */
static void fall_and_slide(int set_late, double friction, double restitution, scene_state *out, int *premise)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id box;
    ga2d_shape_id sh;
    static int tag;
    int i, done = 0;
    memset(out, 0, sizeof *out);
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    if (!w) return;
    static_box(w, 0, -0.5, 20, 0.5);
    box = dynamic_body(w, 0, 0.95);
    ga2d_body_set_velocity(w, box, v2(2, 0));
    sd.friction = (ga2d_real)(set_late ? 0.6 : friction);
    sd.restitution = (ga2d_real)(set_late ? 0 : restitution);
    sd.user_data = &tag;
    sh = add_box(w, box, &sd, 0.5, 0.5);
    CHECK(ga2d_shape_user_data(w, sh) == (void *)&tag);
    for (i = 0; i < 120; ++i) {
        if (set_late && !done && ga2d_world_get_pairs(w, NULL, 0) == 1) {
            *premise &= ga2d_world_get_contacts(w, NULL, 0) == 0;
            /* each setter only for a change: one refreshes both materials */
            if (friction != 0.6) CHECK_RESULT(ga2d_shape_set_friction(w, sh, (ga2d_real)friction), GA2D_OK);
            if (restitution != 0) CHECK_RESULT(ga2d_shape_set_restitution(w, sh, (ga2d_real)restitution), GA2D_OK);
            done = 1;
        }
        ga2d_world_step(w, (ga2d_real)DT);
        if (i % 40 == 39) { /* three records, one per 40 steps */
            ga2d_vec c = ga2d_body_center(w, box), v = ga2d_body_velocity(w, box);
            out->s[i / 40][0] = (double)c.x;
            out->s[i / 40][1] = (double)c.y;
            out->s[i / 40][2] = (double)v.x;
            out->s[i / 40][3] = (double)v.y;
            out->s[i / 40][4] = (double)ga2d_body_angular_velocity(w, box);
        }
    }
    if (set_late) *premise &= done;
    ga2d_world_destroy(w);
}

static void shape_setters_reach_live_contacts(void)
{
    scene_state made, set, left;
    int premise = 1;
    fall_and_slide(0, 0.1, 0.5, &made, &premise);
    fall_and_slide(1, 0.1, 0.5, &set, &premise);
    fall_and_slide(0, 0.6, 0, &left, &premise);
    CHECK(premise);
    CHECK(memcmp(&made, &set, sizeof made) == 0);
    CHECK(memcmp(&made, &left, sizeof made) != 0);
    /* each setter on its own too: friction only, restitution only */
    fall_and_slide(0, 0.1, 0, &made, &premise);
    fall_and_slide(1, 0.1, 0, &set, &premise);
    CHECK(memcmp(&made, &set, sizeof made) == 0 && memcmp(&made, &left, sizeof made) != 0);
    fall_and_slide(0, 0.6, 0.5, &made, &premise);
    fall_and_slide(1, 0.6, 0.5, &set, &premise);
    CHECK(memcmp(&made, &set, sizeof made) == 0 && memcmp(&made, &left, sizeof made) != 0);
}

/* ============================================================ chains */
/* ga2d_chain_get_segments lists a chain's segments in order: segment i of
   an open chain of points p runs p[i] -> p[i+1] with ghosts p[i-1] and
   p[i+2] (its neighbours' far ends), exactly: they are copies.  An open
   end's ghost is made up: the end turns down a right angle (header), so
   p[0] - ghost1 is along the left normal of the first segment (its dot
   with the segment is 0 to rounding of the points' size, and its wedge
   with it is negative: behind); a loop's ghosts wrap round.  A capacity
   below the count fills that many and still returns the count.  Then
   ga2d_chain_destroy removes every segment, and a ball dropped where the
   chain was falls through (free fall: its y is the exact Euler answer to
   rounding). */
static void chain_segments_and_destroy(void)
{
    static const double px[6] = {-4, -2, 0, 1.5, 3, 4}, py[6] = {0, -0.5, 0.2, 0, 0.7, 0.6};
    int loop;
    for (loop = 0; loop < 2; ++loop) {
        ga2d_world *w = ga2d_world_create(NULL);
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_chain_def cd = ga2d_default_chain_def();
        ga2d_vec p[6];
        ga2d_shape_id seg[8], few[8];
        ga2d_chain_id chain;
        ga2d_body_id ground;
        const int n = loop ? 5 : 6, nseg = loop ? 5 : 5;
        int i, got;
        CHECK(w != NULL);
        if (!w) return;
        for (i = 0; i < 6; ++i) p[i] = v2(px[i], py[i]);
        if (loop) { /* a counter-clockwise pentagon */
            for (i = 0; i < 5; ++i) p[i] = v2(3 * cos(2 * 3.14159265358979 * i / 5), 3 * sin(2 * 3.14159265358979 * i / 5));
        }
        ground = ga2d_body_create(w, &d);
        cd.points = p;
        cd.count = n;
        cd.is_loop = loop;
        CHECK_RESULT(ga2d_chain_create_checked(w, ground, &cd, &chain), GA2D_OK);
        got = ga2d_chain_get_segments(w, chain, seg, 8);
        CHECK(got == nseg);
        for (i = 0; i < got && i < 8; ++i) {
            ga2d_geometry g = ga2d_shape_geometry(w, seg[i]);
            const ga2d_chain_segment *cs = &g.as.chain_segment;
            ga2d_vec a = p[i], b = p[(i + 1) % n];
            CHECK(g.type == GA2D_SHAPE_CHAIN_SEGMENT);
            if (g.type != GA2D_SHAPE_CHAIN_SEGMENT) continue;
            CHECK(cs->segment.point1.x == a.x && cs->segment.point1.y == a.y);
            CHECK(cs->segment.point2.x == b.x && cs->segment.point2.y == b.y);
            if (loop || i > 0) {
                ga2d_vec q = p[(i + n - 1) % n];
                CHECK(cs->ghost1.x == q.x && cs->ghost1.y == q.y);
            } else {
                ga2d_vec e = ga2d_vec_sub(b, a), back = ga2d_vec_sub(a, cs->ghost1);
                CHECK(fabs((double)ga2d_dot(back, e)) <= 16 * REAL_EPS * 16 * (double)ga2d_vec_length(back));
                CHECK((double)ga2d_wedge(e, back) > 0); /* a - ghost points left of e: the ghost lies below */
            }
            if (loop || i + 2 < n) {
                ga2d_vec q = p[(i + 2) % n];
                CHECK(cs->ghost2.x == q.x && cs->ghost2.y == q.y);
            } else {
                ga2d_vec e = ga2d_vec_sub(b, a), fwd = ga2d_vec_sub(b, cs->ghost2);
                CHECK(fabs((double)ga2d_dot(fwd, e)) <= 16 * REAL_EPS * 16 * (double)ga2d_vec_length(fwd));
                CHECK((double)ga2d_wedge(e, fwd) > 0);
            }
            CHECK(ga2d_body_id_equal(ga2d_shape_body(w, seg[i]), ground));
        }
        for (i = 0; i < 8; ++i) few[i] = ga2d_shape_id_null();
        CHECK(ga2d_chain_get_segments(w, chain, few, 2) == nseg);
        CHECK(ga2d_shape_id_equal(few[0], seg[0]) && ga2d_shape_id_equal(few[1], seg[1]));
        for (i = 2; i < 8; ++i) CHECK(ga2d_shape_id_is_null(few[i]));
        CHECK_RESULT(ga2d_chain_destroy(w, chain), GA2D_OK);
        for (i = 0; i < nseg; ++i) CHECK(!ga2d_shape_is_valid(w, seg[i]));
        CHECK(ga2d_chain_get_segments(w, chain, NULL, 0) == 0);
        {
            /* a ball dropped from y = 2 at x = 0.1 through where the chain was */
            ga2d_shape_def sd = ga2d_default_shape_def();
            ga2d_body_id ball = dynamic_body(w, 0.1, 2);
            const double h = DT / 4, u = REAL_EPS / 2, nsub = 240;
            double y;
            add_circle(w, ball, &sd, 0.25);
            for (i = 0; i < 60; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
            y = 2 - G * h * h * nsub * (nsub + 1) / 2; /* -3.02 */
            /* |y| <= 3.1, |v| <= 10: the free-fall bound of sensor_free_fall */
            CHECK_NEAR(ga2d_body_center(w, ball).y, y, nsub * u * (3.1 + 2 * nsub * 10 * h));
        }
        {
            ga2d_chain_id bad;
            cd.count = 1;
            CHECK_RESULT(ga2d_chain_create_checked(w, ground, &cd, &bad), GA2D_ERR_TOO_FEW_POINTS);
            CHECK(bad.index1 == 0);
        }
        ga2d_world_destroy(w);
    }
}

/* ============================================================ small functions */
/* Hand answers.  Boxes are closed: touching on an edge or a corner
   overlaps; a gap of any size does not.  The union is the componentwise
   min and max, exactly.  mv_from_bivec puts b in the e12 slot alone;
   mv_sub subtracts every grade (small integers: exact). */
static ga2d_aabb box4(double lx, double ly, double ux, double uy)
{
    ga2d_aabb b;
    b.lower = v2(lx, ly);
    b.upper = v2(ux, uy);
    return b;
}

static void aabb_and_multivector_helpers(void)
{
    ga2d_aabb a = box4(0, 0, 2, 1), u;
    ga2d_bivec bv;
    ga2d_mv m, x, y;
    CHECK(ga2d_aabb_overlaps(a, box4(1, 0.5, 3, 4)));     /* proper overlap */
    CHECK(ga2d_aabb_overlaps(a, box4(2, 0, 3, 1)));       /* shared edge x = 2 */
    CHECK(ga2d_aabb_overlaps(a, box4(-1, 1, 0, 2)));      /* shared corner (0, 1) */
    CHECK(ga2d_aabb_overlaps(a, box4(0.5, 0.2, 1, 0.4))); /* inside */
    CHECK(ga2d_aabb_overlaps(box4(0.5, 0.2, 1, 0.4), a));
    CHECK(!ga2d_aabb_overlaps(a, box4(2.001, 0, 3, 1))); /* apart in x */
    CHECK(!ga2d_aabb_overlaps(a, box4(0, -2, 2, -0.001))); /* apart in y */
    CHECK(!ga2d_aabb_overlaps(box4(-3, 0, -1, 1), a));
    u = ga2d_aabb_union(a, box4(-1, 0.5, 1, 3));
    CHECK(u.lower.x == -1 && u.lower.y == 0 && u.upper.x == 2 && u.upper.y == 3);
    u = ga2d_aabb_union(box4(5, -4, 6, -2), a);
    CHECK(u.lower.x == 0 && u.lower.y == -4 && u.upper.x == 6 && u.upper.y == 1);
    bv.e12 = (ga2d_real)-2.5;
    m = ga2d_mv_from_bivec(bv);
    CHECK(m.s == 0 && m.e1 == 0 && m.e2 == 0 && m.e12 == (ga2d_real)-2.5);
    x = ga2d_mv_make(1, 2, 3, 4);
    y = ga2d_mv_make(8, -1, (ga2d_real)0.5, 6);
    m = ga2d_mv_sub(x, y);
    CHECK(m.s == -7 && m.e1 == 3 && m.e2 == (ga2d_real)2.5 && m.e12 == -2);
    m = ga2d_mv_sub(y, x);
    CHECK(m.s == 7 && m.e1 == -3 && m.e2 == (ga2d_real)-2.5 && m.e12 == 2);
}

/* A shape's broadphase box holds the shape's own box grown by the body's
   margin (GA2D_AABB_MARGIN, 10 cm, or a quarter of the body's extent if
   less: here the extent is 1.5 m, so 10 cm) on every side, for a body at
   rest in a weightless world (nothing to reach further); the body's box is
   the union of its shapes'. */
static void shape_fat_boxes(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id b;
    ga2d_shape_id s1, s2;
    ga2d_circle c;
    ga2d_polygon p = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.25);
    ga2d_aabb f1, f2, fb, un;
    const double m = 0.1, tol = 8 * REAL_EPS * 4; /* coordinates up to 4: a few roundings */
    int i;
    wd.gravity = v2(0, 0);
    w = ga2d_world_create(&wd);
    CHECK(w != NULL);
    if (!w) return;
    b = dynamic_body(w, 0, 0);
    for (i = 0; i < 4; ++i) p.vertices[i].x = (ga2d_real)(p.vertices[i].x - 1);
    s1 = ga2d_shape_create_polygon(w, b, &sd, &p); /* [-1.5, -0.5] x [-0.25, 0.25] */
    c.center = v2(1, 0);
    c.radius = (ga2d_real)0.5;
    s2 = ga2d_shape_create_circle(w, b, &sd, &c); /* [0.5, 1.5] x [-0.5, 0.5] */
    CHECK(!ga2d_shape_id_is_null(s1) && !ga2d_shape_id_is_null(s2));
    CHECK_RESULT(ga2d_world_step(w, (ga2d_real)DT), GA2D_OK);
    f1 = ga2d_shape_fat_aabb(w, s1);
    f2 = ga2d_shape_fat_aabb(w, s2);
    fb = ga2d_body_fat_aabb(w, b);
    CHECK_NEAR(f1.lower.x, -1.5 - m, tol);
    CHECK_NEAR(f1.upper.x, -0.5 + m, tol);
    CHECK_NEAR(f1.lower.y, -0.25 - m, tol);
    CHECK_NEAR(f1.upper.y, 0.25 + m, tol);
    CHECK_NEAR(f2.lower.x, 0.5 - m, tol);
    CHECK_NEAR(f2.upper.x, 1.5 + m, tol);
    CHECK_NEAR(f2.lower.y, -0.5 - m, tol);
    CHECK_NEAR(f2.upper.y, 0.5 + m, tol);
    un = ga2d_aabb_union(f1, f2);
    CHECK(un.lower.x == fb.lower.x && un.lower.y == fb.lower.y && un.upper.x == fb.upper.x && un.upper.y == fb.upper.y);
    ga2d_world_destroy(w);
}


/* ============================================================ restitution threshold */
/* A ball (r 0.25, restitution 0.8) dropped onto the ground at 0.7 and 1.4
   times the world's restitution threshold T (1 m/s by default, and 2):
   slower than T it must not bounce, faster it must.  Dropped from a gap
   v^2 / (2 g), it lands at v.  A bounce leaves at e v, and the ball's
   centre rises (e v)^2 / (2 g) above where it rests: at e v >= 0.8 * 1.4
   m/s that is >= 6.3 cm above its lowest point; no bounce, and it rises
   no more than a slop above its lowest point (a soft contact pushes out
   overlap of under a slop, at most that much).  The check's line is half the bounce's rise, over 6 slops
   from both answers.  1.4 m/s bounces at T = 1 and not at T = 2. */
static double bounce_rise(double threshold, double v)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *w;
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_body_id ball;
    double rise = 0, lowest = 1e30, gap = v * v / (2 * G);
    int i;
    wd.restitution_threshold = (ga2d_real)threshold;
    wd.enable_sleep = 0;
    w = ga2d_world_create(&wd);
    if (!w) return -1;
    static_box(w, 0, -0.5, 5, 0.5);
    ball = dynamic_body(w, 0, 0.25 + gap);
    sd.restitution = (ga2d_real)0.8;
    add_circle(w, ball, &sd, 0.25);
    for (i = 0; i < 120; ++i) {
        double y;
        ga2d_world_step(w, (ga2d_real)DT);
        y = (double)ga2d_body_center(w, ball).y - 0.25;
        if (y < lowest) lowest = y;
        if (y - lowest > rise) rise = y - lowest; /* above the lowest point so far */
    }
    ga2d_world_destroy(w);
    return rise;
}

static void restitution_threshold_decides_bounces(void)
{
    static const double thresholds[2] = {1, 2}, factors[2] = {0.7, 1.4};
    int t, k;
    for (t = 0; t < 2; ++t)
        for (k = 0; k < 2; ++k) {
            double v = thresholds[t] * factors[k], ev = 0.8 * 1.4 * thresholds[0];
            double line = ev * ev / (2 * G) / 2, rise = bounce_rise(thresholds[t], v);
            int bounced = rise > line;
            if (bounced != (factors[k] > 1))
                test_fail(__FILE__, __LINE__, "threshold %.0f m/s, landing at %.1f m/s: rose %.4f m (%s expected)", thresholds[t], v,
                          rise, factors[k] > 1 ? "a bounce" : "no bounce");
            if (!bounced) CHECK(rise <= SLOP);
        }
    /* the same speed on both sides of the two thresholds */
    CHECK(bounce_rise(1, 1.4) > 0.5 * (0.8 * 1.4) * (0.8 * 1.4) / (2 * G));
    CHECK(bounce_rise(2, 1.4) <= SLOP);
}

void suite_features(void)
{
    test_run("features: sensors report what falls through them, at the predicted steps", sensor_free_fall);
    test_run("features: every setter and push wakes a sleeping island", every_setter_and_push_wakes_the_island);
    test_run("features: making a joint wakes both its bodies", making_a_joint_wakes_its_bodies);
    test_run("features: damping, restitution and user data leave a sleeping island asleep",
             setters_that_change_nothing_at_rest_leave_it_asleep);
    test_run("features: the sleep switch", sleep_switch);
    test_run("features: a belt carries a box at its speed at steady state", conveyor_steady_state);
    test_run("features: filters decide contacts in a world", filters_in_a_world);
    test_run("features: the broadphase's category pruning keeps groups and refilters", filters_prune_the_search);
    test_run("features: world switch setters step as the def", world_switch_setters);
    test_run("features: shape friction and restitution setters reach live contacts", shape_setters_reach_live_contacts);
    test_run("features: chain segments, their ghosts, and chain destroy", chain_segments_and_destroy);
    test_run("features: aabb and multivector helpers", aabb_and_multivector_helpers);
    test_run("features: shape fat boxes", shape_fat_boxes);
    test_run("features: the restitution threshold decides what bounces", restitution_threshold_decides_bounces);
}
