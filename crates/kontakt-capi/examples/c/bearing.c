/*
 * The kontakt bearing element from C: a whole bearing as one force element of a
 * multi-body code. For each bearing case file given on the command line (e.g.
 * examples/bearing_7205.toml and examples/bearing_32008x.toml): the element is created,
 * evaluated at a displacement of the inner ring relative to the outer ring, its stiffness
 * is estimated by central differences of the force, the damping is switched on and the
 * element evaluated with a velocity, the ring is pulled out of every contact (status
 * lifted off), and the error paths are tried (NaN, a displacement beyond validity, null
 * pointers). Then a bad case text and a missing file. With a third case file that has a
 * [lubricant] (e.g. examples/bearing_32008x_friction.toml): the friction torque, power and
 * breakdown at the case's speed, at rest (starting torque), with both rings turning, and a
 * speed that is not finite.
 *
 * Build (from the repository root, after `cargo build -p kontakt-capi`):
 *   cc -std=c99 -Icrates/kontakt-capi/include crates/kontakt-capi/examples/c/bearing.c \
 *      target/debug/libkontakt_capi.a -lpthread -ldl -lm -o bearing
 *   ./bearing examples/bearing_7205.toml examples/bearing_32008x.toml \
 *      examples/bearing_32008x_friction.toml
 *
 * Units: displacement dx, dy, dz [mm], tilts tx, ty [rad]; velocities mm/s, rad/s; force
 * [N], moment [N*mm] of the bearing on the inner ring, in the outer ring's frame (z the
 * bearing axis). Output: one "== <label>" line per step, then "key value..." lines
 * (%.17g, so that the numbers round-trip; tests/c_bearing.rs compares them with the Rust
 * API).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "kontakt.h"

static void print_n(const char *key, const double *v, int n) {
    printf("%s", key);
    for (int i = 0; i < n; i++) {
        printf(" %.17g", v[i]);
    }
    printf("\n");
}

/* The force and moment as one 5-vector Fx, Fy, Fz, Mx, My. */
static void reaction(const KontaktBearingResult *r, double f[5]) {
    f[0] = r->force[0];
    f[1] = r->force[1];
    f[2] = r->force[2];
    f[3] = r->moment[0];
    f[4] = r->moment[1];
}

/* Evaluate, print the result (or the error), return the code. */
static int32_t evaluate(KontaktBearingElement *e, const char *label, const double u[5],
                        const double v[5], KontaktBearingResult *r) {
    int32_t code = kontakt_bearing_element_evaluate(e, u, v, r);
    printf("== %s\n", label);
    printf("code %d\n", code);
    if (code != KONTAKT_OK) {
        printf("error %s\n", kontakt_last_error_message());
        return code;
    }
    print_n("displacement", u, 5);
    print_n("velocity", v, 5);
    printf("status %d\n", r->status);
    print_n("force", r->force, 3);
    print_n("moment", r->moment, 3);
    print_n("damping", r->damping, 5);
    print_n("stiffness", &r->stiffness[0][0], 25);
    printf("max_element_load %.17g\n", r->max_element_load);
    printf("iterations %llu\n", (unsigned long long)r->iterations);
    printf("message %s\n", r->message);
    printf("friction_status %d\n", r->friction_status);
    print_n("ring_speeds", r->ring_speeds, 2);
    printf("friction_torque %.17g\n", r->friction_torque);
    printf("friction_inner_ring %.17g\n", r->friction_inner_ring);
    printf("friction_power %.17g\n", r->friction_power);
    print_n("friction_breakdown", r->friction_breakdown, 4);
    return code;
}

/* Print the code and the message of a call expected to fail. */
static void expect_error(const char *label, int32_t code) {
    printf("== %s\n", label);
    printf("code %d\n", code);
    printf("error %s\n", kontakt_last_error_message());
}

/* The element of a case file, or NULL (the error printed to stderr). */
static KontaktBearingElement *open_element(const char *path) {
    KontaktBearingElement *e = NULL;
    if (kontakt_bearing_element_from_file(path, &e) != KONTAKT_OK) {
        fprintf(stderr, "%s: %s\n", path, kontakt_last_error_message());
    }
    return e;
}

static int run(const char *name, const char *path, const double u[5], const double v[5]) {
    KontaktBearingElement *e = open_element(path);
    if (e == NULL) {
        return 1;
    }
    const double rest[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    KontaktBearingResult r;
    char label[64];

    /* 1. The reaction and the stiffness at u. */
    snprintf(label, sizeof label, "%s loaded", name);
    if (evaluate(e, label, u, rest, &r) != KONTAKT_OK) {
        kontakt_bearing_element_free(e);
        return 1;
    }

    /* 2. The stiffness by central differences of the force: K = -dR/du. */
    double fd[5][5];
    for (int j = 0; j < 5; j++) {
        const double h = j < 3 ? 1e-7 : 4e-9; /* mm; rad (1e-7 mm at 25 mm) */
        double up[5], down[5], rp[5], rm[5];
        memcpy(up, u, sizeof up);
        memcpy(down, u, sizeof down);
        up[j] += h;
        down[j] -= h;
        KontaktBearingResult a, b;
        if (kontakt_bearing_element_evaluate(e, up, rest, &a) != KONTAKT_OK ||
            kontakt_bearing_element_evaluate(e, down, rest, &b) != KONTAKT_OK) {
            fprintf(stderr, "%s: %s\n", name, kontakt_last_error_message());
            kontakt_bearing_element_free(e);
            return 1;
        }
        reaction(&a, rp);
        reaction(&b, rm);
        for (int i = 0; i < 5; i++) {
            fd[i][j] = -(rp[i] - rm[i]) / (2.0 * h);
        }
    }
    printf("== %s central differences\n", name);
    print_n("fd_stiffness", &fd[0][0], 25);

    /* 3. Damped: beta = 1e-4 s, the damping matrix is beta K. */
    int32_t code = kontakt_bearing_element_set_damping(e, 1e-4);
    printf("== %s set damping\ncode %d\n", name, code);
    snprintf(label, sizeof label, "%s damped", name);
    evaluate(e, label, u, v, &r);

    /* 4. Pulled 0.2 mm out along the axis: every element lifted off, zero force. */
    const double out[5] = {0.0, 0.0, -0.2, 0.0, 0.0};
    snprintf(label, sizeof label, "%s lifted off", name);
    evaluate(e, label, out, v, &r);

    /* 5. Errors: a NaN tilt, a velocity that is not finite, a displacement beyond the
     * rolling element's diameter, a negative damping, null pointers. */
    double bad[5];
    memcpy(bad, u, sizeof bad);
    bad[3] = NAN;
    snprintf(label, sizeof label, "%s nan", name);
    evaluate(e, label, bad, rest, &r);
    const double fast[5] = {0.0, INFINITY, 0.0, 0.0, 0.0};
    snprintf(label, sizeof label, "%s inf velocity", name);
    evaluate(e, label, u, fast, &r);
    memcpy(bad, u, sizeof bad);
    bad[0] = 20.0;
    snprintf(label, sizeof label, "%s beyond validity", name);
    evaluate(e, label, bad, rest, &r);
    snprintf(label, sizeof label, "%s negative damping", name);
    expect_error(label, kontakt_bearing_element_set_damping(e, -1.0));
    snprintf(label, sizeof label, "%s null element", name);
    expect_error(label, kontakt_bearing_element_evaluate(NULL, u, rest, &r));
    snprintf(label, sizeof label, "%s null displacement", name);
    expect_error(label, kontakt_bearing_element_evaluate(e, NULL, rest, &r));
    snprintf(label, sizeof label, "%s null velocity", name);
    expect_error(label, kontakt_bearing_element_evaluate(e, u, NULL, &r));
    snprintf(label, sizeof label, "%s null out", name);
    expect_error(label, kontakt_bearing_element_evaluate(e, u, rest, NULL));

    /* 6. After the errors the element still answers as in step 3 (damped, same u). */
    snprintf(label, sizeof label, "%s again", name);
    evaluate(e, label, u, v, &r);
    printf("reset %d\n", kontakt_bearing_element_reset(e));

    kontakt_bearing_element_free(e);
    return 0;
}

/* The friction torque of a lubricated bearing at u: at the case's [speed], at rest, with
 * both rings turning (rad/s), and a speed that is not finite (refused, speeds kept). */
static int friction(const char *path, const double u[5]) {
    KontaktBearingElement *e = open_element(path);
    if (e == NULL) {
        return 1;
    }
    const double rest[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    KontaktBearingResult r;
    evaluate(e, "friction case speed", u, rest, &r);
    expect_error("friction set rest", kontakt_bearing_element_set_speeds(e, 0.0, 0.0));
    evaluate(e, "friction at rest", u, rest, &r);
    expect_error("friction set turning", kontakt_bearing_element_set_speeds(e, -50.0, 20.0));
    evaluate(e, "friction turning", u, rest, &r);
    expect_error("friction nan speed", kontakt_bearing_element_set_speeds(e, 10.0, NAN));
    evaluate(e, "friction after nan", u, rest, &r);
    expect_error("friction null element", kontakt_bearing_element_set_speeds(NULL, 1.0, 0.0));
    kontakt_bearing_element_free(e);
    return 0;
}

int main(int argc, char **argv) {
    if (argc != 3 && argc != 4) {
        fprintf(stderr,
                "usage: %s BALL_BEARING.toml TAPERED_ROLLER_BEARING.toml [LUBRICATED.toml]\n",
                argv[0]);
        return 2;
    }
    printf("kontakt %s\n", kontakt_version());
    /* displacement dx, dy, dz [mm], tx, ty [rad]; velocity mm/s, rad/s */
    const double u_ball[5] = {0.01, 0.003, 0.02, 2e-4, -1e-4};
    const double u_trb[5] = {0.01, -0.002, 0.015, 1e-4, 5e-5};
    const double v[5] = {3.0, -1.0, 2.0, 0.05, -0.02};
    if (run("ball", argv[1], u_ball, v) != 0 || run("tapered", argv[2], u_trb, v) != 0) {
        return 1;
    }
    if (argc == 4 && friction(argv[3], u_trb) != 0) {
        return 1;
    }

    /* Creation errors: a case without its bearing, null text, null out, a missing file. */
    KontaktBearingElement *e = (KontaktBearingElement *)&e; /* must be set to NULL */
    expect_error("bad case", kontakt_bearing_element_from_toml("method = \"bearing\"\n", &e));
    printf("out_is_null %d\n", e == NULL);
    expect_error("null toml", kontakt_bearing_element_from_toml(NULL, &e));
    expect_error("null out", kontakt_bearing_element_from_toml("method = \"bearing\"\n", NULL));
    expect_error("missing file", kontakt_bearing_element_from_file("no/such/bearing.toml", &e));
    expect_error("null element reset", kontakt_bearing_element_reset(NULL));
    kontakt_bearing_element_free(NULL);
    return 0;
}
