/*
 * dem_case.c — the DEM dictionaries (dem_case.h). Selection of contact
 * sub-models and integrators by name goes through model_select (doc/design.md
 * C3), so an unknown name lists the valid ones at its file and line.
 */
#include "dem/dem_case.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "core/select.h"

static const int dims_density[7] = {1, -3, 0, 0, 0, 0, 0};
static const int dims_pressure[7] = {1, -1, -2, 0, 0, 0, 0};
static const int dims_length[7] = {0, 1, 0, 0, 0, 0, 0};

/* Re-issue a library message at a dictionary entry. */
static int at_key(const struct dict *d, const char *key, int rc)
{
    char msg[512];
    snprintf(msg, sizeof msg, "%s", sim_error_message());
    return dict_error(d, key, rc, "%s", msg);
}

static int read_material(const struct dict *p, struct contact_coeffs *c)
{
    TRY(dict_get_scalar_dim(p, "rho", dims_density, &c->rho));
    TRY(dict_get_scalar_dim(p, "E", dims_pressure, &c->E));
    TRY(dict_get_scalar(p, "nu", &c->nu));
    TRY(dict_get_scalar(p, "mu", &c->mu));
    TRY(dict_get_scalar(p, "e", &c->e));
    static const char *const keys[] = {"E", "nu", "e", "mu", "rho"};
    int rc = contact_coeffs_init(c);
    if (rc == SIM_OK)
        return SIM_OK;
    const char *msg = sim_error_message();
    const char *key = "rho";
    for (int k = 0; k < 5; k++) {
        char pat[16];
        snprintf(pat, sizeof pat, " %s = ", keys[k]);
        if (strstr(msg, pat)) {
            key = keys[k];
            break;
        }
    }
    return at_key(p, key, rc);
}

#define TABLE(t) ((const void *const *)(t))

const struct model_choice dem_choices[] = {
    { "constant/demProperties", "contact/normal", TABLE(contact_normal_table) },
    { "constant/demProperties", "contact/damping",
      TABLE(contact_damping_table) },
    { "constant/demProperties", "contact/tangential",
      TABLE(contact_tangential_table) },
    { "constant/demProperties", "contact/rolling",
      TABLE(contact_rolling_table) },
    { "constant/demProperties", "contact/twisting",
      TABLE(contact_twisting_table) },
    { "constant/demProperties", "contact/tangentialStiffness",
      TABLE(contact_stiffness_table) },
    { "system/demSolution", "integrator", TABLE(dem_integrator_table) },
    { NULL, NULL, NULL }
};

int dem_read_properties(const struct dict *props, struct dem *d)
{
    struct contact_law *law = &d->law;
    memset(&law->c, 0, sizeof law->c);
    TRY(read_material(props, &law->c));
    const struct dict *c;
    TRY(dict_get_dict(props, "contact", &c));
    const void *m;
    TRY(model_select(c, "normal", "DEM normal contact", 
                     (const void *const *)contact_normal_table, "hertz", &m));
    law->normal = m;
    TRY(model_select(c, "damping", "DEM contact damping",
                     (const void *const *)contact_damping_table,
                     "restitution", &m));
    law->damping = m;
    TRY(model_select(c, "tangential", "DEM tangential contact",
                     (const void *const *)contact_tangential_table, "coulomb",
                     &m));
    law->tangential = m;
    TRY(model_select(c, "rolling", "DEM rolling resistance",
                     (const void *const *)contact_rolling_table, "none", &m));
    law->rolling = m;
    TRY(model_select(c, "twisting", "DEM twisting resistance",
                     (const void *const *)contact_twisting_table, "none", &m));
    law->twisting = m;
    TRY(model_select(c, "tangentialStiffness", "DEM tangential stiffness",
                     (const void *const *)contact_stiffness_table, "mindlin",
                     &m));
    law->stiffness = m;
    if (law->normal == &contact_normal_linear) {
        TRY(dict_get_scalar_or(c, "linearCoeffs/stiffness", 0.0,
                               &law->c.kn_linear));
        if (law->c.kn_linear < 0)
            return dict_error(c, "linearCoeffs/stiffness", SIM_ERR_DICT,
                              "stiffness %g must be >= 0 (0: from E, nu, R)",
                              law->c.kn_linear);
    }
    if (law->rolling == &contact_rolling_constant_torque) {
        TRY(dict_get_scalar(c, "constantTorqueCoeffs/rollingFriction",
                            &law->c.mu_roll));
        if (!(law->c.mu_roll >= 0))
            return dict_error(c, "constantTorqueCoeffs/rollingFriction",
                              SIM_ERR_DICT, "rollingFriction must be >= 0");
    }
    if (law->rolling == &contact_rolling_viscous) {
        TRY(dict_get_scalar(c, "viscousCoeffs/rollingViscosity",
                            &law->c.eta_roll));
        if (!(law->c.eta_roll >= 0))
            return dict_error(c, "viscousCoeffs/rollingViscosity",
                              SIM_ERR_DICT, "rollingViscosity must be >= 0");
    }
    if (law->twisting == &contact_twisting_viscous) {
        TRY(dict_get_scalar(c, "twistingViscousCoeffs/twistingViscosity",
                            &law->c.eta_twist));
        if (!(law->c.eta_twist >= 0))
            return dict_error(c, "twistingViscousCoeffs/twistingViscosity",
                              SIM_ERR_DICT, "twistingViscosity must be >= 0");
    }
    /* the material was checked above: only the model constants are new */
    TRY(contact_law_init(law));
    if (law->tangential != &contact_tangential_none && law->c.mu == 0)
        log_warn("%s: tangential model %s with mu = 0 gives no friction",
                 dict_file(props), law->tangential->name);
    return SIM_OK;
}

#define DEM_ERK_TABLE_NAMES                                                \
    "HEUN_EULER_2_1_2 BOGACKI_SHAMPINE_4_2_3 ARK324L2SA_ERK_4_2_3 "        \
    "ZONNEVELD_5_3_4 ARK436L2SA_ERK_6_3_4 SAYFY_ABURUB_6_3_4 "             \
    "CASH_KARP_6_4_5 FEHLBERG_6_4_5 DORMAND_PRINCE_7_4_5 "                 \
    "ARK548L2SA_ERK_8_4_5 VERNER_8_5_6 FEHLBERG_13_7_8"

static int erk_table_known(const char *name)
{
    static const char *const names[] = {
        "ARKODE_HEUN_EULER_2_1_2", "ARKODE_BOGACKI_SHAMPINE_4_2_3",
        "ARKODE_ARK324L2SA_ERK_4_2_3", "ARKODE_ZONNEVELD_5_3_4",
        "ARKODE_ARK436L2SA_ERK_6_3_4", "ARKODE_SAYFY_ABURUB_6_3_4",
        "ARKODE_CASH_KARP_6_4_5", "ARKODE_FEHLBERG_6_4_5",
        "ARKODE_DORMAND_PRINCE_7_4_5", "ARKODE_ARK548L2SA_ERK_8_4_5",
        "ARKODE_VERNER_8_5_6", "ARKODE_FEHLBERG_13_7_8", NULL};
    for (int k = 0; names[k]; k++)
        if (strcmp(names[k], name) == 0)
            return 1;
    return 0;
}

static const char *const action_words[] = {"refuse", "relax", NULL};

/* Keys of sub-dictionary `sub` of d: read them in the sub-dictionary when
 * it exists (so that a misspelt key gets a "did you mean" suggestion),
 * else as scoped keys of d (defaults are then recorded under that name). */
struct scope {
    const struct dict *d;
    const char *prefix;
    char buf[128];
};

static int scope_open(const struct dict *d, const char *sub, struct scope *s)
{
    const struct dict *sd = NULL;
    TRY(dict_find_dict(d, sub, &sd));
    s->d = sd ? sd : d;
    s->prefix = sd ? "" : sub;
    return SIM_OK;
}

static const char *key(struct scope *s, const char *name)
{
    snprintf(s->buf, sizeof s->buf, "%s%s%s", s->prefix,
             s->prefix[0] ? "/" : "", name);
    return s->buf;
}

static int read_arkode(const struct dict *sol, struct dem *d,
                       struct dem_solution *s)
{
    struct dem_integrator_params *p = &s->params;
    const char *table;
    double vref = sqrt(9.81 * fmax(d->rmax, 1e-6));
    struct scope a;
    TRY(scope_open(sol, "arkodeCoeffs", &a));
    TRY(dict_get_scalar_or(a.d, key(&a, "rtol"), 1e-4, &p->rtol));
    TRY(dict_get_scalar_or(a.d, key(&a, "atolPosition"), 1e-4 * d->rmin,
                           &p->atol_x));
    TRY(dict_get_scalar_or(a.d, key(&a, "atolVelocity"), 1e-4 * vref,
                           &p->atol_v));
    TRY(dict_get_scalar_or(a.d, key(&a, "atolOmega"),
                           1e-4 * vref / fmax(d->rmin, 1e-9), &p->atol_w));
    TRY(dict_get_scalar_or(a.d, key(&a, "stabilitySafety"), 0.5,
                           &p->safety));
    TRY(dict_get_string_or(a.d, key(&a, "table"), "DORMAND_PRINCE_7_4_5",
                           &table));
    snprintf(s->table, sizeof s->table, "ARKODE_%s", table);
    p->table = s->table;
    if (!erk_table_known(s->table))
        return dict_error(a.d, key(&a, "table"), SIM_ERR_DICT,
                          "unknown ERK table '%s'; valid: %s", table,
                          DEM_ERK_TABLE_NAMES);
    long ms;
    TRY(dict_get_label_or(a.d, key(&a, "maxSteps"), 100000000L, &ms));
    p->max_steps = ms;
    const char *ev;
    TRY(dict_get_string_or(a.d, key(&a, "slipEvents"), "auto", &ev));
    p->slip_events = !strcmp(ev, "auto") ? 0 : !strcmp(ev, "on") ? 1
                     : !strcmp(ev, "off") ? 2 : -1;
    if (p->slip_events < 0)
        return dict_error(a.d, key(&a, "slipEvents"), SIM_ERR_DICT,
                          "slipEvents '%s': valid: auto on off", ev);
    const char *bad = !(p->rtol > 0) ? "rtol"
                      : !(p->atol_x > 0) ? "atolPosition"
                      : !(p->atol_v > 0) ? "atolVelocity"
                      : !(p->atol_w > 0) ? "atolOmega" : NULL;
    if (bad)
        return dict_error(a.d, key(&a, bad), SIM_ERR_DICT, "%s must be > 0",
                          bad);
    if (!(p->safety > 0 && p->safety < 1))
        return dict_error(a.d, key(&a, "stabilitySafety"), SIM_ERR_DICT,
                          "stabilitySafety %g must be in (0, 1)", p->safety);
    return SIM_OK;
}

#define VERLET_MIN_FRACTION 1e-6

static int read_verlet(const struct dict *sol, struct dem *d,
                       struct dem_solution *s)
{
    struct scope v;
    TRY(scope_open(sol, "verletCoeffs", &v));
    TRY(dict_get_scalar_or(v.d, key(&v, "deltaT"), 0.0, &s->params.dt));
    TRY(dict_get_scalar_or(v.d, key(&v, "rayleighFraction"), 0.2,
                           &s->params.dt_fraction));
    if (!(s->params.dt >= 0))
        return dict_error(v.d, key(&v, "deltaT"), SIM_ERR_DICT,
                          "deltaT must be >= 0 (0: rayleighFraction)");
    /* A step a million times below the bound is a typo, not a choice:
     * 1e-300 overflowed the step count of an advance, and the grains
     * silently did not move. */
    if (!(s->params.dt_fraction >= VERLET_MIN_FRACTION &&
          s->params.dt_fraction <= 1))
        return dict_error(v.d, key(&v, "rayleighFraction"), SIM_ERR_DICT,
                          "rayleighFraction %g must be in [%g, 1]",
                          s->params.dt_fraction, VERLET_MIN_FRACTION);
    double dtr = d->dt_stable;
    if (s->params.dt > 0 && dtr > 0 &&
        s->params.dt < VERLET_MIN_FRACTION * dtr)
        return dict_error(v.d, key(&v, "deltaT"), SIM_ERR_DICT,
                          "deltaT %g s is below %g of the stability bound "
                          "%g s (Rayleigh step, eq. 38)", s->params.dt,
                          VERLET_MIN_FRACTION, dtr);
    if (s->params.dt > 0 && dtr > 0 && s->params.dt > dtr)
        return dict_error(v.d, key(&v, "deltaT"), SIM_ERR_DICT,
                          "deltaT %g s is above the stability bound %g s "
                          "(Rayleigh step, eq. 38, R_min = %g m%s)",
                          s->params.dt, dtr, d->rmin,
                          dtr < d->dt_rayleigh ? "; linear law: 2/omega of "
                          "the stiffest contact" : "");
    return SIM_OK;
}

static void mark_all_used(const struct dict *d, const char *key)
{
    const struct dict *sub = NULL;
    dict_mark_used(d, key);
    if (!dict_is_dict(d, key) || dict_find_dict(d, key, &sub) || !sub)
        return;
    for (int i = 0; i < dict_size(sub); i++)
        dict_mark_used(sub, dict_key_at(sub, i));
}

int dem_read_solution(const struct dict *sol, struct dem *d,
                      struct dem_solution *s)
{
    memset(s, 0, sizeof *s);
    const void *m;
    TRY(model_select(sol, "integrator", "DEM integrator",
                     (const void *const *)dem_integrator_table, "arkode", &m));
    s->integrator = m;
    /* the coefficients of the integrator not selected may stay in the
     * file (switching is one word), so they are not reported unused;
     * auto reads both */
    int ark = s->integrator != &dem_integrator_verlet;
    int verlet = s->integrator != &dem_integrator_arkode;
    if (!verlet)
        mark_all_used(sol, "verletCoeffs");
    if (!ark)
        mark_all_used(sol, "arkodeCoeffs");
    if (ark)
        TRY(read_arkode(sol, d, s));
    if (verlet)
        TRY(read_verlet(sol, d, s));
    TRY(dict_get_scalar_dim_or(sol, "neighbour/skin", dims_length,
                               0.2 * d->rmax, &d->nl.skin));
    if (!(d->nl.skin > 0))
        return dict_error(sol, "neighbour/skin", SIM_ERR_DICT,
                          "skin %g must be > 0", d->nl.skin);
    TRY(dict_get_scalar_or(sol, "initialOverlap/maxFraction", 0.05,
                           &s->max_overlap));
    int act;
    TRY(dict_get_word_or(sol, "initialOverlap/action", action_words, 0, &act));
    s->relax_overlap = act;
    if (!(s->max_overlap >= 0 && s->max_overlap < 1))
        return dict_error(sol, "initialOverlap/maxFraction", SIM_ERR_DICT,
                          "maxFraction %g must be in [0, 1)", s->max_overlap);
    if (dict_has(sol, "domain")) {
        TRY(dict_get_vector(sol, "domain/min", 3, d->dom_lo));
        TRY(dict_get_vector(sol, "domain/max", 3, d->dom_hi));
        TRY(dict_get_bool_or(sol, "domain/removeOutside", 0,
                             &d->remove_outside));
        for (int a = 0; a < 3; a++)
            if (!(d->dom_hi[a] > d->dom_lo[a]))
                return dict_error(sol, "domain/max", SIM_ERR_DICT,
                                  "domain max must exceed min in every "
                                  "direction");
        d->have_domain = 1;
    }
    return SIM_OK;
}
