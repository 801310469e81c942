/*
 * The kontakt contact element from C: the roller end face (body 1) against the rib
 * (body 2) of the torus-torus-14 pairing (Wirsching et al. 2020, Table 1), once with the
 * Hertz back-end and once with PimP. For each: the reference placement (identity poses:
 * the surfaces touch), the roller pressed 4 um along the contact normal while turning,
 * the roller moved 0.1 mm away (separated), and a NaN pose (an error naming pose1).
 *
 * Build (from the repository root, after `cargo build -p kontakt-capi`):
 *   cc -std=c99 -Icrates/kontakt-capi/include crates/kontakt-capi/examples/c/element.c \
 *      target/debug/libkontakt_capi.a -lpthread -ldl -lm -o element
 *   ./element
 *
 * Units: mm, N, N*mm, mm/s, rad/s, MPa, W; every vector in the world frame.
 * Output: one "== <label>" line per evaluation, then "key value..." lines (%.17g, so that
 * the numbers round-trip; the test tests/c_example.rs compares them with the Rust API).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "kontakt.h"

static const char *CASE_TEMPLATE =
    "name = \"roller end face on the rib\"\n"
    "method = \"element\"\n"
    "[geometry]\n"
    "kind = \"roller_rib\"\n"
    "pairing = \"torus-torus-14\"\n"
    "[element]\n"
    "backend = \"%s\"\n";

static void print_vec(const char *key, const double v[3]) {
    printf("%s %.17g %.17g %.17g\n", key, v[0], v[1], v[2]);
}

/* Evaluate, print the result (or the error), return the code. */
static int32_t evaluate(KontaktElement *e, const char *label, const double pose1[7],
                        const double pose2[7], const double twist1[6],
                        const double twist2[6], KontaktResult *r) {
    int32_t code = kontakt_element_evaluate(e, pose1, pose2, twist1, twist2, r);
    printf("== %s\n", label);
    printf("code %d\n", code);
    if (code != KONTAKT_OK) {
        printf("error %s\n", kontakt_last_error_message());
        return code;
    }
    printf("status %d\n", r->status);
    printf("separation %.17g\n", r->separation);
    printf("approach %.17g\n", r->approach);
    print_vec("point", r->point);
    print_vec("normal", r->normal);
    printf("normal_force %.17g\n", r->normal_force);
    printf("damping_force %.17g\n", r->damping_force);
    print_vec("friction_force", r->friction_force);
    print_vec("friction_moment", r->friction_moment);
    printf("friction_power %.17g\n", r->friction_power);
    print_vec("force1", r->force1);
    print_vec("moment1", r->moment1);
    print_vec("moment2", r->moment2);
    printf("max_pressure %.17g\n", r->max_pressure);
    printf("contact_area %.17g\n", r->contact_area);
    printf("iterations %llu\n", (unsigned long long)r->iterations);
    printf("message %s\n", r->message);
    return code;
}

static int run(const char *backend) {
    char toml[512];
    snprintf(toml, sizeof toml, CASE_TEMPLATE, backend);
    KontaktElement *e = NULL;
    if (kontakt_element_from_toml(toml, &e) != KONTAKT_OK) {
        fprintf(stderr, "%s: %s\n", backend, kontakt_last_error_message());
        return 1;
    }
    /* Poses: x, y, z [mm], then the unit quaternion w, x, y, z. Twists: v [mm/s], w [rad/s]. */
    const double identity[7] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0};
    const double rest[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    const double turning[6] = {5.0, 0.0, 0.0, 0.0, 0.0, 10.0};
    KontaktResult r;
    char label[64];

    /* 1. The reference placement: the surfaces touch; the result gives the normal. */
    snprintf(label, sizeof label, "%s reference", backend);
    if (evaluate(e, label, identity, identity, rest, rest, &r) != KONTAKT_OK) {
        kontakt_element_free(e);
        return 1;
    }
    const double n[3] = {r.normal[0], r.normal[1], r.normal[2]};

    /* 2. Body 1 pressed 4 um into body 2 (against the normal, which points into body 1). */
    const double delta = 0.004;
    const double pressed[7] = {-n[0] * delta, -n[1] * delta, -n[2] * delta, 1.0, 0.0, 0.0, 0.0};
    snprintf(label, sizeof label, "%s pressed", backend);
    if (evaluate(e, label, pressed, identity, turning, rest, &r) == KONTAKT_OK) {
        printf("force2 %.17g %.17g %.17g\n", -r.force1[0], -r.force1[1], -r.force1[2]);
    }

    /* 3. Body 1 moved 0.1 mm away: separated, zero force. */
    const double apart[7] = {n[0] * 0.1, n[1] * 0.1, n[2] * 0.1, 1.0, 0.0, 0.0, 0.0};
    snprintf(label, sizeof label, "%s apart", backend);
    evaluate(e, label, apart, identity, rest, rest, &r);

    /* 4. A NaN pose: code KONTAKT_INVALID_INPUT, the message names pose1. */
    const double bad[7] = {NAN, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0};
    snprintf(label, sizeof label, "%s nan", backend);
    evaluate(e, label, bad, identity, rest, rest, &r);

    kontakt_element_free(e);
    return 0;
}

int main(void) {
    printf("kontakt %s\n", kontakt_version());
    if (run("hertz") != 0 || run("pimp") != 0) {
        return 1;
    }
    return 0;
}
