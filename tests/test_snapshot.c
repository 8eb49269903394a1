/* Snapshots (issue 8): save, load, and step on bit for bit; refuse what is
   truncated, corrupted or of another version, leaving the world exactly as
   it was. */
#include "test.h"
#include "determinism_scene.h"
#include <stdlib.h>
#include <string.h>

/* The header, as ga2d_physics.h lays it out: magic[8], six uint32 (version
   first), payload size (uint64) and the payload's FNV-1a checksum (uint64)
   at byte 40; the payload starts at byte 48.  snapshot_header_ok below
   checks these offsets against a real snapshot before they are used. */
#define SNAP_VERSION_AT 8
#define SNAP_CHECKSUM_AT 40
#define SNAP_PAYLOAD_AT 48

static unsigned char *save(const ga2d_world *w, size_t *size)
{
    unsigned char *buf;
    *size = ga2d_world_snapshot_size(w);
    buf = (unsigned char *)malloc(*size);
    if (buf && ga2d_world_snapshot_save(w, buf, *size) != GA2D_OK) {
        free(buf);
        buf = NULL;
    }
    return buf;
}

static void reseal(unsigned char *buf, size_t size)
{
    uint64_t h = dscene_fnv(14695981039346656037ull, buf + SNAP_PAYLOAD_AT, size - SNAP_PAYLOAD_AT);
    memcpy(buf + SNAP_CHECKSUM_AT, &h, sizeof h);
}

/* The world is as it was: its snapshot has the same bytes. */
static int same_world(const ga2d_world *w, const unsigned char *ref, size_t ref_size)
{
    size_t n;
    unsigned char *now = save(w, &n);
    int same = now && n == ref_size && memcmp(now, ref, n) == 0;
    free(now);
    return same;
}

static void steps(dscene *s, int n)
{
    int i;
    for (i = 0; i < n; ++i) ga2d_world_step(s->w, (ga2d_real)1 / 60);
}

/* Save after 200 steps of the mixed scene (a pile still moving, contacts
   with warm-start impulses, some bodies asleep, some queued for pairs);
   step 300 more: that hash is the truth.  Loading the snapshot back into
   the same world, or into a fresh default world, and stepping 300 gives
   the same bits (the ids stay valid: slots and generations are saved). */
static void load_then_step_is_bit_identical(void)
{
    dscene s, f;
    unsigned char *snap, *again;
    size_t size, size2;
    uint64_t truth, same, fresh;
    CHECK(dscene_build(&s));
    steps(&s, 200);
    snap = save(s.w, &size);
    CHECK(snap != NULL);
    if (!snap) return;
    steps(&s, 300);
    truth = dscene_hash(&s);
    CHECK_RESULT(ga2d_world_snapshot_load(s.w, snap, size), GA2D_OK);
    again = save(s.w, &size2);
    /* the same size (not the same bytes: tree leaves and list links are
       rebuilt, and the bytes hold the library's slots as they are) */
    CHECK(again && size2 == size);
    free(again);
    steps(&s, 300);
    same = dscene_hash(&s);
    CHECK(same == truth);
    /* into another world object: f keeps its own allocator, takes the rest */
    f = s;
    f.w = ga2d_world_create(NULL);
    CHECK(f.w != NULL);
    CHECK_RESULT(ga2d_world_snapshot_load(f.w, snap, size), GA2D_OK);
    steps(&f, 300);
    fresh = dscene_hash(&f);
    CHECK(fresh == truth);
    ga2d_world_destroy(f.w);
    ga2d_world_destroy(s.w);
    free(snap);
}

/* A counting allocator: the bytes a world holds now. */
typedef struct count_alloc { long long live; } count_alloc;
static void *ca_alloc(size_t n, void *ctx) { ((count_alloc *)ctx)->live += (long long)n; return malloc(n); }
static void ca_free(void *p, size_t n, void *ctx) { ((count_alloc *)ctx)->live -= (long long)n; free(p); }

/* ga2d_world_compact moves contacts and rebuilds the pair set and body
   lists, which the solver's canonical order makes invisible: the mixed
   scene with its churn (bodies made and destroyed, so the contact pool
   has holes) steps to the same bits with a compaction every 50 steps as
   without.  Memory: after destroying every dynamic body but one and a
   step (the pairs go with them), compacting must give back bytes, and a
   second compaction finds nothing more to give (the pool is already its
   own size). */
static void compact_keeps_bits_and_gives_memory_back(void)
{
    dscene a, b;
    count_alloc ca = {0};
    int step, i;
    long long before, after, again;
    CHECK(dscene_build(&a) && dscene_build(&b));
    for (step = 0; step < 400; ++step) {
        dscene_churn(&a, step);
        dscene_churn(&b, step);
        if (step % 50 == 25) CHECK_RESULT(ga2d_world_compact(b.w), GA2D_OK);
        ga2d_world_step(a.w, (ga2d_real)1 / 60);
        ga2d_world_step(b.w, (ga2d_real)1 / 60);
    }
    CHECK(dscene_hash(&a) == dscene_hash(&b));
    ga2d_world_destroy(a.w);
    ga2d_world_destroy(b.w);
    {
        ga2d_world_def wd = ga2d_default_world_def();
        ga2d_body_def d = ga2d_default_body_def();
        ga2d_world *w;
        ga2d_body_id ids[400];
        wd.allocator.alloc = ca_alloc;
        wd.allocator.free = ca_free;
        wd.allocator.ctx = &ca;
        w = ga2d_world_create(&wd);
        CHECK(w != NULL);
        if (!w) return;
        d.polygon = ga2d_polygon_box(20, 1);
        d.position = ga2d_vec_make(0, -1);
        ga2d_body_create(w, &d);
        d.type = GA2D_BODY_DYNAMIC;
        d.polygon = ga2d_polygon_box((ga2d_real)0.25, (ga2d_real)0.25);
        for (i = 0; i < 400; ++i) {
            d.position = ga2d_vec_make((ga2d_real)(-10 + 0.5 * (i % 40)), (ga2d_real)(0.25 + 0.5 * (i / 40)));
            ids[i] = ga2d_body_create(w, &d);
        }
        for (step = 0; step < 30; ++step) ga2d_world_step(w, (ga2d_real)1 / 60);
        for (i = 1; i < 400; ++i) ga2d_body_destroy(w, ids[i]);
        ga2d_world_step(w, (ga2d_real)1 / 60);
        before = ca.live;
        CHECK_RESULT(ga2d_world_compact(w), GA2D_OK);
        after = ca.live;
        CHECK_RESULT(ga2d_world_compact(w), GA2D_OK);
        again = ca.live;
        CHECK(after < before);
        CHECK(again == after);
        CHECK(ga2d_body_is_valid(w, ids[0]));
        for (step = 0; step < 10; ++step) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
        if (getenv("GA2D_TEST_VERBOSE"))
            printf("snapshot: compact, 400 boxes down to 1: %lld -> %lld bytes\n", before, after);
        ga2d_world_destroy(w);
        CHECK(ca.live == 0);
    }
}

static void snapshot_header_ok(const unsigned char *snap, size_t size)
{
    uint32_t version;
    uint64_t payload, sum;
    CHECK(memcmp(snap, "GA2DSNAP", 8) == 0);
    memcpy(&version, snap + SNAP_VERSION_AT, sizeof version);
    CHECK(version >= 1);
    memcpy(&payload, snap + SNAP_CHECKSUM_AT - 8, sizeof payload);
    CHECK(payload == size - SNAP_PAYLOAD_AT);
    memcpy(&sum, snap + SNAP_CHECKSUM_AT, sizeof sum);
    CHECK(sum == dscene_fnv(14695981039346656037ull, snap + SNAP_PAYLOAD_AT, size - SNAP_PAYLOAD_AT));
}

/* Every refusal leaves the world's own snapshot byte for byte as it was
   just before the attempt (a refused load touches nothing). */
static void bad_snapshots_are_refused(void)
{
    dscene s;
    unsigned char *snap, *bad, *before;
    size_t size, before_size, n, step;
    unsigned char small[16];
    int refused = 0, accepted = 0;
    test_rng rng = {7};
    CHECK(dscene_build(&s));
    steps(&s, 150);
    snap = save(s.w, &size);
    CHECK(snap != NULL);
    if (!snap) return;
    snapshot_header_ok(snap, size);
    steps(&s, 20); /* the world is elsewhere now */
    before = save(s.w, &before_size);
    bad = (unsigned char *)malloc(size);
    CHECK(before && bad);
    if (!before || !bad) return;

    /* too small a buffer for save: refused, buffer untouched */
    memset(small, 0xAB, sizeof small);
    CHECK_RESULT(ga2d_world_snapshot_save(s.w, small, sizeof small), GA2D_ERR_BUFFER_TOO_SMALL);
    CHECK(small[0] == 0xAB && small[15] == 0xAB);
    CHECK_RESULT(ga2d_world_snapshot_load(s.w, NULL, size), GA2D_ERR_INVALID_ARGUMENT);

    /* truncated: every length short of the whole (sampled every 7 bytes
       and at both ends) */
    step = 7;
    for (n = 0; n < size; n = n + step < size ? n + step : (n + 1 < size ? size - 1 : size))
        if (ga2d_world_snapshot_load(s.w, snap, n) != GA2D_ERR_BAD_SNAPSHOT) ++accepted;
    CHECK(accepted == 0);
    CHECK(same_world(s.w, before, before_size));

    /* one byte changed anywhere (checksum left as it was): refused */
    for (n = 0; n < 400; ++n) {
        size_t at = (size_t)rng_int(&rng, 0, (int)size - 1);
        memcpy(bad, snap, size);
        bad[at] ^= (unsigned char)(1u << rng_int(&rng, 0, 7));
        if (ga2d_world_snapshot_load(s.w, bad, size) != GA2D_ERR_BAD_SNAPSHOT) ++accepted;
    }
    CHECK(accepted == 0);
    CHECK(same_world(s.w, before, before_size));

    /* another version, resealed: refused */
    memcpy(bad, snap, size);
    bad[SNAP_VERSION_AT] ^= 0x40;
    CHECK_RESULT(ga2d_world_snapshot_load(s.w, bad, size), GA2D_ERR_BAD_SNAPSHOT);
    CHECK(same_world(s.w, before, before_size));

    /* corrupted and resealed, so that only the checks on the content stand
       between the bytes and the world: 4 bytes set to random values in the
       payload.  Each load is refused (world unchanged) or accepted and
       then steps without fault (ASan and UBSan watch); the accepted world
       is replaced by a good snapshot each time. */
    for (n = 0; n < 300; ++n) {
        int k;
        memcpy(bad, snap, size);
        for (k = 0; k < 4; ++k) bad[rng_int(&rng, SNAP_PAYLOAD_AT, (int)size - 1)] = (unsigned char)rng_next(&rng);
        reseal(bad, size);
        if (ga2d_world_snapshot_load(s.w, bad, size) == GA2D_OK) {
            ++accepted;
            steps(&s, 3);
            CHECK_RESULT(ga2d_world_snapshot_load(s.w, snap, size), GA2D_OK);
            free(before);
            before = save(s.w, &before_size); /* the state the next refusal must keep */
            if (!before) break;
        } else {
            ++refused;
            if (!same_world(s.w, before, before_size)) {
                CHECK(0);
                break;
            }
        }
    }
    CHECK(refused > 0);
    if (getenv("GA2D_TEST_VERBOSE"))
        printf("snapshot: %lu bytes for %d bodies; resealed corruptions: %d refused, %d accepted and stepped\n",
               (unsigned long)size, s.count, refused, accepted);
    free(bad);
    free(before);
    free(snap);
    ga2d_world_destroy(s.w);
}

/* A world's own snapshot loads into a fresh world and saves to the same
   bytes. */
static void round_trips(const ga2d_world *w)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_world *t = ga2d_world_create(&wd);
    size_t size;
    unsigned char *snap = save(w, &size);
    CHECK(t != NULL && snap != NULL);
    if (t && snap) {
        CHECK_RESULT(ga2d_world_snapshot_load(t, snap, size), GA2D_OK);
        CHECK(same_world(t, snap, size));
    }
    ga2d_world_destroy(t);
    free(snap);
}

/* Frictions are any finite values >= 0, and a contact's is their
   geometric mean, sqrt(mu_a mu_b): the largest real against 4 (at
   creation) and against itself (set later, reaching the touching
   contact) overflow the product, yet the mean is finite and the world's
   snapshot, which refuses an infinite contact friction, must load.  (The
   fuzz finding: frictions FLT_MAX and 1e8.)  A box resting on the ground
   stays there, finite, stepped on. */
static void huge_frictions_round_trip(void)
{
    ga2d_world_def wd = ga2d_default_world_def();
    ga2d_body_def d = ga2d_default_body_def();
    ga2d_world *w = ga2d_world_create(&wd);
    ga2d_body_id box;
    ga2d_shape_id shape;
    ga2d_contact_data cd[4];
    ga2d_vec v;
    int i;
    CHECK(w != NULL);
    if (!w) return;
    d.polygon = ga2d_polygon_box(5, 1);
    d.position = ga2d_vec_make(0, -1);
    d.friction = (ga2d_real)REAL_MAX;
    CHECK(ga2d_body_is_valid(w, ga2d_body_create(w, &d)));
    d.type = GA2D_BODY_DYNAMIC;
    d.polygon = ga2d_polygon_box((ga2d_real)0.5, (ga2d_real)0.5);
    d.position = ga2d_vec_make(0, (ga2d_real)0.5);
    d.friction = 4;
    box = ga2d_body_create(w, &d);
    CHECK(ga2d_body_get_shapes(w, box, &shape, 1) == 1);
    for (i = 0; i < 10; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
    CHECK(ga2d_world_get_contacts(w, cd, 4) == 1);
    round_trips(w);
    CHECK_RESULT(ga2d_shape_set_friction(w, shape, (ga2d_real)REAL_MAX), GA2D_OK);
    round_trips(w);
    for (i = 0; i < 30; ++i) CHECK_RESULT(ga2d_world_step(w, (ga2d_real)1 / 60), GA2D_OK);
    round_trips(w);
    v = ga2d_body_velocity(w, box);
    CHECK(ga2d_world_get_contacts(w, cd, 4) == 1);
    CHECK(isfinite((double)v.x) && isfinite((double)v.y) && fabs((double)v.x) < 1e-3 && fabs((double)v.y) < 1e-3);
    ga2d_world_destroy(w);
}

void suite_snapshot(void)
{
    test_run("snapshot: load, then step, is bit-identical", load_then_step_is_bit_identical);
    test_run("snapshot: truncated, corrupted, other version refused, world unchanged", bad_snapshots_are_refused);
    test_run("snapshot: ga2d_world_compact keeps the bits and gives memory back", compact_keeps_bits_and_gives_memory_back);
    test_run("snapshot: contacts between huge frictions (their product overflows) round-trip", huge_frictions_round_trip);
}
