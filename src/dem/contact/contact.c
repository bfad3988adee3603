/*
 * contact.c — the generic part of the contact law: derived material
 * constants, input validation, the constants that depend on the selected
 * sub-models (contact_law_init), the fixed order in which sub-models are
 * called, and the Rayleigh step (doc/theory.md A.6, eq. 38). No physics of a
 * particular sub-model lives here.
 */
#include "dem/contact/contact.h"

#include <math.h>

#include "core/error.h"

int contact_coeffs_init(struct contact_coeffs *c)
{
    if (!(c->E > 0))
        return sim_error(SIM_ERR_INPUT, "Young's modulus E = %g must be > 0",
                         c->E);
    if (!(c->nu > -1 && c->nu < 0.5))
        return sim_error(SIM_ERR_INPUT,
                         "Poisson ratio nu = %g must be in (-1, 0.5)", c->nu);
    if (!(c->e > 0 && c->e <= 1))
        return sim_error(SIM_ERR_INPUT,
                         "restitution coefficient e = %g must be in (0, 1]",
                         c->e);
    if (!(c->mu >= 0))
        return sim_error(SIM_ERR_INPUT,
                         "friction coefficient mu = %g must be >= 0", c->mu);
    if (!(c->rho > 0))
        return sim_error(SIM_ERR_INPUT, "density rho = %g must be > 0",
                         c->rho);
    c->estar = c->E / (2.0 * (1.0 - c->nu * c->nu));
    double le = log(c->e);
    c->beta = -le / sqrt(le * le + M_PI * M_PI);
    return SIM_OK;
}

int contact_law_init(struct contact_law *law)
{
    struct contact_coeffs *c = &law->c;
    int rc = contact_coeffs_init(c);
    if (rc != SIM_OK)
        return rc;
    const struct contact_stiffness_ops *st =
        law->stiffness ? law->stiffness : &contact_stiffness_mindlin;
    double p = law->normal->exponent;
    c->ratio_t = st->ratio(c->nu, p);
    c->hertz_tn = sqrt(c->ratio_t / 1.5);
    c->zeta = law->damping->zeta ? law->damping->zeta(c->e, p) : 0;
    return SIM_OK;
}

double contact_chi(const struct contact_coeffs *c, double rstar)
{
    return 4.0 / 3.0 * c->estar * sqrt(rstar);
}

double contact_rayleigh_step(const struct contact_coeffs *c, double rmin)
{
    return M_PI * rmin / (0.1631 * c->nu + 0.8766)
           * sqrt(2.0 * c->rho * (1.0 + c->nu) / c->E);
}

void contact_eval(const struct contact_law *law, const struct contact_geom *g,
                  const double *h, double tau, double *hnew,
                  struct contact_result *out)
{
    double fel, kn, kt, eta_n, eta_t;
    law->normal->eval(&law->c, g, &fel, &kn, &kt);
    law->damping->eval(&law->c, g, kn, kt, &eta_n, &eta_t);
    /* No tensile cut-off: the contact ends when the overlap vanishes, which
     * keeps the linear law's restitution exact (LIGGGHTS' default too). */
    double fn = fel + eta_n * g->vn;
    law->tangential->eval(&law->c, g, fn, kt, eta_t, h, tau, hnew, out->ft);
    /* rolling and twisting resistance scale with the elastic force (Ai et
     * al. 2011; LIGGGHTS cdt): the dashpot would brake a rolling grain
     * harder while it bounces, A0-23 */
    law->rolling->eval(&law->c, g, fel, out->mroll);
    if (law->twisting && law->twisting != &contact_twisting_none) {
        double mt[3];
        law->twisting->eval(&law->c, g, fel, mt);
        for (int a = 0; a < 3; a++)
            out->mroll[a] += mt[a];
    }
    for (int a = 0; a < 3; a++)
        out->f[a] = -fn * g->n[a] + out->ft[a];
    out->fn = fn;
    out->kn = kn;
    out->kt = kt;
    out->eta_t = eta_t;
}
