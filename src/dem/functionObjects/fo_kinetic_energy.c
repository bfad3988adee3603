/*
 * fo_kinetic_energy.c — total kinetic energy of the grains,
 *   E_k = sum_k (1/2 m_k |v_k|^2 + 1/2 I_k |w_k|^2),
 * the settling criterion of E2-09 and Fig. 3 of Xie et al. (2025) (which
 * plots the translational part, doc/theory.md A.12.1).
 * Columns: time, E_trans, E_rot, E_total [J], grains, contacts (grain-grain,
 * grain-wall). Keys: none beyond the schedule.
 * The grains' fields by name (velocity, omega, mass, inverseInertia); the
 * contact counts are the solver's.
 */
#include "core/error.h"
#include "dem/dem.h"
#include "dem/functionObjects/dem_fo.h"

static int create(const struct dict *d, const struct fo_scene *s, void **data)
{
    (void)d, (void)s;
    *data = NULL;
    return SIM_OK;
}

static int header(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data, (void)s;
    fprintf(f, "# kinetic energy of the grains [J]\n"
               "# time E_trans E_rot E_total grains contacts wallContacts\n");
    return SIM_OK;
}

static int execute(void *data, const struct fo_scene *s, FILE *f)
{
    (void)data;
    const struct dem *d = s->solver;
    const void *p[4];
    static const char *const who = "kineticEnergy";
    TRY(store_require(s->store, who, "velocity", VTU_FLOAT64, 3, &p[0]));
    TRY(store_require(s->store, who, "omega", VTU_FLOAT64, 3, &p[1]));
    TRY(store_require(s->store, who, "mass", VTU_FLOAT64, 1, &p[2]));
    TRY(store_require(s->store, who, "inverseInertia", VTU_FLOAT64, 1,
                      &p[3]));
    const double *v = p[0], *w = p[1], *m = p[2], *inv_i = p[3];
    const size_t n = s->store->n;
    double et = 0, er = 0;
    for (size_t i = 0; i < n; i++) {
        double v2 = 0, w2 = 0;
        for (int a = 0; a < 3; a++) {
            v2 += v[3 * i + a] * v[3 * i + a];
            w2 += w[3 * i + a] * w[3 * i + a];
        }
        et += 0.5 * m[i] * v2;
        er += 0.5 * w2 / inv_i[i];
    }
    fprintf(f, "%.9g %.9g %.9g %.9g %zu %ld %ld\n", s->time, et, er, et + er,
            n, d->ncontacts, d->nwall_contacts);
    return SIM_OK;
}

static void destroy(void *data)
{
    (void)data;
}

const struct fo_ops dem_fo_kinetic_energy = {
    .name = "kineticEnergy",
    .reference = "E2-09; Xie et al. 2025 Fig. 3",
    .file = "",
    .create = create,
    .header = header,
    .execute = execute,
    .destroy = destroy,
};
