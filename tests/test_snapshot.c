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

void suite_snapshot(void)
{
    test_run("snapshot: load, then step, is bit-identical", load_then_step_is_bit_identical);
    test_run("snapshot: truncated, corrupted, other version refused, world unchanged", bad_snapshots_are_refused);
}
