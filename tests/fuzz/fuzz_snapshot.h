/* Snapshot-loader fuzzing: raw bytes -> a buffer loaded into a world built
   from a fixed small scene (a ground with a wall segment and a sensor disc
   over the stack, a stack, a falling triangle, a kinematic body, a ball, a
   capsule and a rounded box resting on an open chain, a destroyed body's,
   shape's and chain's free slots, after some steps, so that contacts,
   warm-start impulses and the sensor's visitors exist; and joints of the
   four kinds, with a free joint slot): every shape type, sensor visitor
   lists, chain lists and joints reach the loader.

   The buffer is either the input itself, or the scene's own snapshot
   edited by the input (bytes set, flipped, words and reals written at
   aligned places, truncated or extended) with, on request, its header's
   payload size and checksum made to match again: the header is
   documented as magic, version and the build's sizes (32 bytes), then the
   payload size and an FNV-1a checksum of the payload (8 bytes each), so
   edits reach the loader's checks of every body and contact instead of
   stopping at the checksum.  The allocator may fail during the load.

   Checked:
     - a refused buffer (any error) leaves the world bit-identical: its
       snapshot before and after are the same bytes;
     - an error is BAD_SNAPSHOT, or OUT_OF_MEMORY when an allocation
       failed;
     - an accepted buffer gives a world that saves and loads again to the
       same bytes, and steps without crashing, with every awake body
       finite after steps that report OK or NOT_FINITE (containment), the
       lines drawn (segment shapes, joints) finite, and no more joints
       solved than there are;
     - nothing leaks (the allocator gets every byte back). */
#ifndef GA2D_FUZZ_SNAPSHOT_H
#define GA2D_FUZZ_SNAPSHOT_H

#include "fuzz_common.h"

#define FS_HEADER 48          /* documented: 32 bytes of ids and sizes, then two 64-bit fields */
#define FS_MAX_EXTRA 4096

typedef struct fs_snap { unsigned char *p; size_t n; } fs_snap;

static int fs_save(const ga2d_world *w, fs_snap *s)
{
    s->n = ga2d_world_snapshot_size(w);
    s->p = (unsigned char *)malloc(s->n ? s->n : 1);
    if (!s->p) return 0;
    return ga2d_world_snapshot_save(w, s->p, s->n) == GA2D_OK;
}

static uint64_t fs_fnv1a(const unsigned char *p, size_t n)
{
    uint64_t h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

static ga2d_world *fs_scene(fz_alloc *a, ga2d_body_id *ids, int *n)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_shape_def sd = ga2d_default_shape_def();
    ga2d_chain_def cd = ga2d_default_chain_def();
    ga2d_world *w;
    ga2d_vec pts[4];
    ga2d_chain_id gone;
    int i;
    fz_alloc_attach(a, &wd);
    w = ga2d_world_create(&wd);
    if (!w) return NULL;
    *n = 0;
    d.position = ga2d_vec_make(0, -1);
    d.polygon = ga2d_polygon_box(10, 1);
    ids[(*n)++] = ga2d_body_create(w, &d);
    {
        /* the ground's other shapes: a wall segment (a conveyor), and a
           sensor disc over the stack */
        ga2d_segment wall;
        ga2d_circle zone;
        wall.point1 = ga2d_vec_make(-10, 1);
        wall.point2 = ga2d_vec_make(-10, 4);
        sd.tangent_speed = 1;
        ga2d_shape_create_segment(w, ids[0], &sd, &wall);
        sd = ga2d_default_shape_def();
        sd.is_sensor = 1;
        zone.center = ga2d_vec_make(0, 2);
        zone.radius = (ga2d_real)1.5;
        ga2d_shape_create_circle(w, ids[0], &sd, &zone);
    }
    for (i = 0; i < 3; ++i) {
        d = ga2d_default_body_def();
        d.type = GA2D_BODY_DYNAMIC;
        d.position = ga2d_vec_make((ga2d_real)(0.1 * i), (ga2d_real)(0.5 + i));
        d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
        d.restitution = (ga2d_real)(0.2 * i);
        ids[(*n)++] = ga2d_body_create(w, &d);
    }
    d = ga2d_default_body_def();
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(2, 2);
    d.polygon = ga2d_polygon_regular(3, (ga2d_real)0.4);
    d.angular_velocity = 2;
    ids[(*n)++] = ga2d_body_create(w, &d);
    d = ga2d_default_body_def();
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    d.type = GA2D_BODY_KINEMATIC;
    d.position = ga2d_vec_make(-3, 1);
    d.velocity = ga2d_vec_make((ga2d_real)0.5, 0);
    ids[(*n)++] = ga2d_body_create(w, &d);
    {
        /* terrain: an open chain on a static body, and a ball (hits and
           pre-solve on), a capsule and a rounded box resting on it */
        ga2d_circle ball, spare;
        ga2d_capsule cap;
        ga2d_polygon rounded = ga2d_polygon_rounded_box((ga2d_real)0.4, (ga2d_real)0.3, (ga2d_real)0.1);
        ga2d_shape_id spare_id;
        d = ga2d_default_body_def();
        ids[(*n)++] = ga2d_body_create(w, &d);
        for (i = 0; i < 4; ++i) pts[i] = ga2d_vec_make((ga2d_real)(3 + 2 * i), (ga2d_real)(0.01 * (i & 1)));
        cd.points = pts;
        cd.count = 4;
        ga2d_chain_create(w, ids[*n - 1], &cd);
        cd.count = 3; /* a loop made and destroyed: a free chain slot */
        cd.is_loop = 1;
        gone = ga2d_chain_create(w, ids[*n - 1], &cd);
        ga2d_chain_destroy(w, gone);
        d = ga2d_default_body_def();
        d.type = GA2D_BODY_DYNAMIC;
        d.position = ga2d_vec_make((ga2d_real)4.5, (ga2d_real)0.31);
        ids[(*n)++] = ga2d_body_create(w, &d);
        sd = ga2d_default_shape_def();
        sd.enable_hit_events = sd.enable_pre_solve_events = 1;
        ball.center = ga2d_vec_make(0, 0);
        ball.radius = (ga2d_real)0.3;
        ga2d_shape_create_circle(w, ids[*n - 1], &sd, &ball);
        d.position = ga2d_vec_make(6, (ga2d_real)0.22);
        d.angular_velocity = 1;
        ids[(*n)++] = ga2d_body_create(w, &d);
        sd = ga2d_default_shape_def();
        cap.center1 = ga2d_vec_make((ga2d_real)-0.4, 0);
        cap.center2 = ga2d_vec_make((ga2d_real)0.4, 0);
        cap.radius = (ga2d_real)0.2;
        ga2d_shape_create_capsule(w, ids[*n - 1], &sd, &cap);
        /* a shape made and destroyed: a free shape slot */
        spare.center = ga2d_vec_make(0, 1);
        spare.radius = (ga2d_real)0.1;
        spare_id = ga2d_shape_create_circle(w, ids[*n - 1], &sd, &spare);
        ga2d_shape_destroy(w, spare_id, 1);
        d.position = ga2d_vec_make((ga2d_real)7.5, (ga2d_real)0.32);
        d.angular_velocity = 0;
        ids[(*n)++] = ga2d_body_create(w, &d);
        ga2d_shape_create_polygon(w, ids[*n - 1], &sd, &rounded);
    }
    {
        /* joints: a pendulum on the ground (revolute: limit, motor), a bob
           below it on a distance joint (spring, range, motor), a box
           welded to that (soft), a motor joint from the ground driving the
           triangle, and a joint made and destroyed: a free joint slot */
        ga2d_revolute_joint_def rj = ga2d_default_revolute_joint_def();
        ga2d_distance_joint_def dj = ga2d_default_distance_joint_def();
        ga2d_weld_joint_def wj = ga2d_default_weld_joint_def();
        ga2d_motor_joint_def mj = ga2d_default_motor_joint_def();
        ga2d_body_id pend, bob, box;
        d = ga2d_default_body_def();
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = ga2d_polygon_box((ga2d_real)0.1, (ga2d_real)0.5);
        d.position = ga2d_vec_make(-6, (ga2d_real)5.5);
        pend = ids[(*n)++] = ga2d_body_create(w, &d);
        d.polygon = ga2d_polygon_regular(5, (ga2d_real)0.25);
        d.position = ga2d_vec_make(-6, 3);
        bob = ids[(*n)++] = ga2d_body_create(w, &d);
        d.polygon = ga2d_polygon_box((ga2d_real)0.2, (ga2d_real)0.2);
        d.position = ga2d_vec_make((ga2d_real)-5.5, 3);
        box = ids[(*n)++] = ga2d_body_create(w, &d);
        rj.body_a = ids[0];
        rj.body_b = pend;
        rj.local_anchor_a = ga2d_vec_make(-6, 7);
        rj.local_anchor_b = ga2d_vec_make(0, (ga2d_real)0.5);
        rj.enable_limit = rj.enable_motor = 1;
        rj.lower_angle = (ga2d_real)-0.5;
        rj.upper_angle = (ga2d_real)0.75;
        rj.motor_speed = 1;
        rj.max_motor_torque = 5;
        rj.reference_angle = (ga2d_real)0.1;
        ga2d_revolute_joint_create(w, &rj);
        dj.body_a = pend;
        dj.body_b = bob;
        dj.local_anchor_a = ga2d_vec_make(0, (ga2d_real)-0.5);
        dj.length = (ga2d_real)1.5;
        dj.enable_spring = dj.enable_limit = dj.enable_motor = 1;
        dj.hertz = 3;
        dj.damping_ratio = (ga2d_real)0.5;
        dj.min_length = 1;
        dj.max_length = 2;
        dj.max_motor_force = 2;
        dj.motor_speed = (ga2d_real)0.25;
        dj.collide_connected = 1;
        ga2d_distance_joint_create(w, &dj);
        wj.body_a = bob;
        wj.body_b = box;
        wj.local_anchor_a = ga2d_vec_make((ga2d_real)0.25, 0);
        wj.local_anchor_b = ga2d_vec_make((ga2d_real)-0.25, 0);
        wj.angular_hertz = 5;
        wj.angular_damping_ratio = 1;
        ga2d_weld_joint_create(w, &wj);
        mj.body_a = ids[0];
        mj.body_b = ids[4];
        mj.linear_offset = ga2d_vec_make(2, 4);
        mj.angular_offset = (ga2d_real)0.5;
        mj.max_force = 20;
        mj.max_torque = 2;
        ga2d_joint_destroy(w, ga2d_weld_joint_create(w, &wj));
        ga2d_motor_joint_create(w, &mj);
    }
    d = ga2d_default_body_def();
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    d.type = GA2D_BODY_DYNAMIC;
    d.position = ga2d_vec_make(5, 5);
    ids[(*n)++] = ga2d_body_create(w, &d);
    for (i = 0; i < 8; ++i) ga2d_world_step(w, (ga2d_real)(1.0 / 60));
    ga2d_body_destroy(w, ids[*n - 1]); /* a free slot */
    return w;
}

/* Every live body with a polygon, circle or capsule, found through the
   debug draw (which names each shape's body; a body with several shapes
   comes once per shape, in a row): awake moving ones must be finite.  A
   body with only segments or none is not seen. */
typedef struct fs_bodies { ga2d_body_id ids[64]; int n; } fs_bodies;

static void fs_add(fs_bodies *b, ga2d_body_id id)
{
    if (b->n > 0 && ga2d_body_id_equal(b->ids[b->n - 1], id)) return;
    if (b->n < 64) b->ids[b->n++] = id;
}

static void fs_collect(ga2d_body_id id, const ga2d_polygon *p, ga2d_transform x, uint32_t color, void *ctx)
{
    (void)p;
    (void)x;
    (void)color;
    fs_add((fs_bodies *)ctx, id);
}

static void fs_collect_circle(ga2d_body_id id, ga2d_vec c, ga2d_real r, ga2d_vec axis, uint32_t color, void *ctx)
{
    (void)c;
    (void)r;
    (void)axis;
    (void)color;
    fs_add((fs_bodies *)ctx, id);
}

static void fs_collect_capsule(ga2d_body_id id, ga2d_vec c1, ga2d_vec c2, ga2d_real r, uint32_t color, void *ctx)
{
    (void)c1;
    (void)c2;
    (void)r;
    (void)color;
    fs_add((fs_bodies *)ctx, id);
}

/* Segments (segment shapes, the joints' three lines): finite ends. */
static void fs_segment(ga2d_vec a, ga2d_vec b, uint32_t color, void *ctx)
{
    (void)color;
    (void)ctx;
    FUZZ_CHECK(fz_finite_vec(a) && fz_finite_vec(b));
}

static void fs_check_finite(const ga2d_world *w)
{
    fs_bodies all;
    ga2d_debug_draw dd = ga2d_default_debug_draw();
    ga2d_world_counters counts = ga2d_world_get_counters(w);
    int i;
    all.n = 0;
    /* after a step: the joints it solved are among those there are */
    FUZZ_CHECK(counts.joint_count >= 0 && counts.joints_solved >= 0 && counts.joints_solved <= counts.joint_count);
    dd.segment = fs_segment;
    dd.polygon = fs_collect;
    dd.circle = fs_collect_circle;
    dd.capsule = fs_collect_capsule;
    dd.context = &all;
    FUZZ_CHECK(ga2d_world_draw(w, &dd) == GA2D_OK);
    FUZZ_CHECK(all.n <= ga2d_world_get_counters(w).body_count || all.n == 64);
    for (i = 0; i < all.n; ++i) {
        ga2d_body_id id = all.ids[i];
        ga2d_vec c, v;
        ga2d_rotor q;
        ga2d_shape_id shapes[16], seen[16];
        int k, j, ns, nv;
        FUZZ_CHECK(ga2d_body_is_valid(w, id));
        /* its shapes are its own; a sensor's visitors are live shapes of
           other bodies */
        ns = ga2d_body_get_shapes(w, id, shapes, 16);
        FUZZ_CHECK(ns >= 1);
        for (k = 0; k < ns && k < 16; ++k) {
            FUZZ_CHECK(ga2d_shape_is_valid(w, shapes[k]) && ga2d_body_id_equal(ga2d_shape_body(w, shapes[k]), id));
            nv = ga2d_shape_get_sensor_overlaps(w, shapes[k], seen, 16);
            FUZZ_CHECK(nv >= 0);
            for (j = 0; j < nv && j < 16; ++j)
                FUZZ_CHECK(ga2d_shape_is_valid(w, seen[j]) && !ga2d_body_id_equal(ga2d_shape_body(w, seen[j]), id));
        }
        if (!ga2d_body_is_awake(w, id) || ga2d_body_get_type(w, id) == GA2D_BODY_STATIC) continue;
        c = ga2d_body_center(w, id);
        v = ga2d_body_velocity(w, id);
        q = ga2d_body_rotor(w, id);
        FUZZ_CHECK(fz_finite_vec(c) && fz_finite_vec(v) && fz_finite((double)q.c) && fz_finite((double)q.s));
        FUZZ_CHECK(fz_finite((double)ga2d_body_angular_velocity(w, id)));
    }
}

static int fuzz_snapshot_one(const uint8_t *data, size_t size)
{
    fz_reader rd;
    fz_alloc a, a2;
    ga2d_body_id ids[16];
    int n = 0, i;
    ga2d_world *w, *w2;
    fs_snap before, after, good;
    unsigned char *buf;
    size_t len;
    unsigned mode, fail;
    ga2d_result r;
    long failures;
    memset(&a, 0, sizeof a);
    memset(&a2, 0, sizeof a2);
    fz_init(&rd, data, size);
    w = fs_scene(&a, ids, &n);
    FUZZ_CHECK(w != NULL);
    if (!w) return 0;
    FUZZ_CHECK(fs_save(w, &before));
    mode = fz_u8(&rd);
    fail = fz_u8(&rd);

    if (mode < 32) {
        /* the input itself */
        len = rd.n - rd.i;
        buf = (unsigned char *)malloc(len ? len : 1);
        FUZZ_CHECK(buf != NULL);
        if (len) memcpy(buf, rd.p + rd.i, len);
    } else {
        /* the scene's snapshot, edited */
        size_t cap = before.n + FS_MAX_EXTRA;
        int edits = 1 + fz_pick(&rd, 8);
        buf = (unsigned char *)malloc(cap);
        FUZZ_CHECK(buf != NULL);
        memcpy(buf, before.p, before.n);
        len = before.n;
        for (i = 0; i < edits && fz_more(&rd); ++i) {
            unsigned op = fz_u8(&rd) % 8;
            size_t at = len ? (size_t)fz_u32(&rd) % len : 0;
            switch (op) {
            case 0: if (len) buf[at] = (unsigned char)fz_u8(&rd); break;
            case 1: if (len) buf[at] ^= (unsigned char)(1u << (fz_u8(&rd) & 7)); break;
            case 2: { /* a 32-bit word at an aligned place */
                uint32_t v;
                static const uint32_t words[8] = {0, 1, 0xFFFFFFFFu, 0x7FFFFFFFu, 0x80000000u, 2, 1000000, 0xFFFFFFFEu};
                unsigned k = fz_u8(&rd);
                v = k < 128 ? words[k % 8] : fz_u32(&rd);
                at &= ~(size_t)3;
                if (at + 4 <= len) memcpy(buf + at, &v, 4);
                break;
            }
            case 3: { /* a real at an aligned place */
                ga2d_real x = fz_special(fz_u8(&rd));
                at &= ~(size_t)(sizeof x - 1);
                if (at + sizeof x <= len) memcpy(buf + at, &x, sizeof x);
                break;
            }
            case 4: len = len ? (size_t)fz_u32(&rd) % len : 0; break; /* truncate */
            case 5: { /* extend with input bytes */
                size_t more = (size_t)fz_u16(&rd) % 256;
                while (more-- && len < cap) buf[len++] = (unsigned char)fz_u8(&rd);
                break;
            }
            case 6: { /* copy a run from elsewhere in the buffer (a body over another) */
                size_t from = len ? (size_t)fz_u32(&rd) % len : 0, run = (size_t)fz_u16(&rd) % 512;
                if (from + run > len) run = len - from;
                if (at + run > len) run = len - at;
                memmove(buf + at, buf + from, run);
                break;
            }
            default: { /* a 64-bit word */
                uint64_t v = fz_u8(&rd) < 128 ? (uint64_t)(int64_t)(int8_t)fz_u8(&rd) : fz_u64(&rd);
                at &= ~(size_t)7;
                if (at + 8 <= len) memcpy(buf + at, &v, 8);
                break;
            }
            }
        }
        if ((mode & 1) && len >= FS_HEADER) {
            /* make the header's payload size and checksum agree again */
            uint64_t payload = (uint64_t)(len - FS_HEADER), sum = fs_fnv1a(buf + FS_HEADER, len - FS_HEADER);
            memcpy(buf + 32, &payload, 8);
            memcpy(buf + 40, &sum, 8);
        }
    }

    /* the load, with an allocation failing in it on request */
    if (fail >= 128) a.fail_at = a.attempts + 1 + (long)(fail - 128) % 16;
    failures = a.failures;
    r = ga2d_world_snapshot_load(w, buf ? buf : (const unsigned char *)"", len);
    FUZZ_CHECK((int)r >= 0 && r < GA2D_RESULT_COUNT);
    a.fail_at = 0;
    if (r != GA2D_OK) {
        FUZZ_CHECK(r == GA2D_ERR_BAD_SNAPSHOT || r == GA2D_ERR_OUT_OF_MEMORY);
        if (r == GA2D_ERR_OUT_OF_MEMORY) FUZZ_CHECK(a.failures != failures);
        /* refused: the world is exactly as it was */
        FUZZ_CHECK(fs_save(w, &after));
        FUZZ_CHECK(after.n == before.n && memcmp(after.p, before.p, before.n) == 0);
        free(after.p);
    } else {
        /* accepted: it saves, and that loads into another world and saves
           to the same bytes */
        ga2d_body_id ids2[16];
        int n2 = 0;
        FUZZ_CHECK(fs_save(w, &good));
        w2 = fs_scene(&a2, ids2, &n2);
        FUZZ_CHECK(w2 != NULL);
        if (w2) {
            FUZZ_CHECK(ga2d_world_snapshot_load(w2, good.p, good.n) == GA2D_OK);
            FUZZ_CHECK(fs_save(w2, &after));
            FUZZ_CHECK(after.n == good.n && memcmp(after.p, good.p, good.n) == 0);
            free(after.p);
            ga2d_world_destroy(w2);
            FUZZ_CHECK(a2.live_bytes == 0 && a2.live_blocks == 0);
        }
        free(good.p);
        /* and it steps */
        for (i = 0; i < 5; ++i) {
            r = ga2d_world_step(w, (ga2d_real)(1.0 / 60));
            /* TOO_LARGE: the saved gravity and substeps may exceed the step's
               g h^2 bound at 1/60 s */
            FUZZ_CHECK(r == GA2D_OK || r == GA2D_ERR_NOT_FINITE || r == GA2D_ERR_INVALID_ARGUMENT || r == GA2D_ERR_TOO_LARGE);
            if (r == GA2D_OK || r == GA2D_ERR_NOT_FINITE) fs_check_finite(w);
        }
        {
            ga2d_debug_draw dd = ga2d_default_debug_draw();
            dd.draw_aabbs = dd.draw_contacts = dd.draw_centers = 1;
            FUZZ_CHECK(ga2d_world_draw(w, &dd) == GA2D_OK);
            (void)ga2d_world_get_contacts(w, NULL, 0);
        }
    }
    free(buf);
    free(before.p);
    ga2d_world_destroy(w);
    FUZZ_CHECK(a.live_bytes == 0 && a.live_blocks == 0);
    return 0;
}

#endif
