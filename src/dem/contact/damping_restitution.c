/*
 * damping_restitution.c — the dashpot that returns the restitution
 * coefficient e exactly, for the linear and the Hertz law
 * (doc/theory.md A0-22):
 *
 *   eta^n = 2 zeta sqrt(kn m*),   eta^t = 2 zeta sqrt(kt m*)
 *
 * with kn the tangent normal stiffness (p chi delta^(p-1) for F_el =
 * chi delta^p) and kt the tangential spring. Scaling the overlap by
 * delta_0 = (m* v_0^2/chi)^(1/(p+1)) and the time by delta_0/v_0 turns a
 * normal impact at speed v_0 into
 *
 *   x'' = -x^p - 2 zeta sqrt(p) x^((p-1)/2) x',   x(0) = 0, x'(0) = 1,
 *
 * which no longer contains v_0, chi or m*: the rebound speed ratio
 * e = -x'(t_end), at the first return to x = 0, depends on zeta and p
 * only (Antypov and Elliott 2011, EPL 94:50004, for p = 3/2). The contact
 * ends when the overlap vanishes (no tensile cut-off, as in contact.c).
 * For p = 1 the ODE is the damped oscillator, e = exp(-zeta pi/sqrt(1 -
 * zeta^2)), so zeta = beta = -ln e/sqrt(ln^2 e + pi^2) (Xie et al. 2025
 * eq. 23). For other p, zeta(e) is found once at set-up
 * (contact_law_init, cached in contact_coeffs.zeta) by integrating the ODE
 * (classical Runge-Kutta, 2e-4 time units per step, refined where the
 * contact ends: e to about 1e-7) inside an Illinois regula falsi
 * on ln e. eta^t uses the same zeta with kt, as LIGGGHTS does with its
 * Tsuji coefficient (A0-22); the tangential restitution is not a target.
 * Reference: Antypov and Elliott (2011); Tsuji et al. (1992) for the
 * delta^(1/4) dashpot; Thornton, Cummins and Cleary (2013) Powder
 * Technol. 233:30, sect. 4, for the speed independence.
 */
#include <math.h>

#include "dem/contact/contact.h"

static double beta_of(double e)
{
    double le = log(e);
    return -le / sqrt(le * le + M_PI * M_PI);
}

/* x'' of the dimensionless impact; negative overlaps (inside a step that
 * crosses zero) see no force. */
static double accel(double x, double v, double c, double p)
{
    if (x < 0)
        return 0;
    if (p == 1.5) {
        double q = sqrt(x);
        return -x * q - c * sqrt(q) * v;
    }
    return -pow(x, p) - c * pow(x, 0.5 * (p - 1)) * v;
}

/* One classical Runge-Kutta step of the dimensionless impact. */
static void rk4(double *x, double *v, double h, double c, double p)
{
    double k1x = *v, k1v = accel(*x, *v, c, p);
    double x2 = *x + 0.5 * h * k1x, v2 = *v + 0.5 * h * k1v;
    double k2x = v2, k2v = accel(x2, v2, c, p);
    double x3 = *x + 0.5 * h * k2x, v3 = *v + 0.5 * h * k2v;
    double k3x = v3, k3v = accel(x3, v3, c, p);
    double x4 = *x + h * k3x, v4 = *v + h * k3v;
    double k4x = v4, k4v = accel(x4, v4, c, p);
    *x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    *v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
}

double contact_restitution_of_zeta(double zeta, double p)
{
    double h = 2e-4, t = 0;
    double c = 2.0 * zeta * sqrt(p);
    double x = 0, v = 1;
    /* the undamped contact lasts 3.2 (p = 3/2) to pi time units; damping
     * lengthens it, and a strongly overdamped one creeps out: e = 0. The
     * step that leaves the contact is redone with steps 16 times smaller
     * (the force jumps to zero there) until it is 1e-10 long. */
    while (t < 1000) {
        double xn = x, vn = v;
        rk4(&xn, &vn, h, c, p);
        if (xn > 0 || t == 0) {
            x = xn, v = vn, t += h;
            continue;
        }
        if (h > 1e-10) {
            h /= 16;
            continue;
        }
        double f = x / (x - xn);
        return -(v + f * (vn - v));
    }
    return 0;
}

double contact_zeta_of_restitution(double e, double p)
{
    if (e >= 1)
        return 0;
    if (p == 1)
        return beta_of(e);
    /* bracket: e(zeta) falls monotonically from 1 at zeta = 0 */
    double target = log(e);
    double a = 0, fa = -target;
    double b = beta_of(e), fb = log(contact_restitution_of_zeta(b, p)) - target;
    while (fb > 0) {
        a = b, fa = fb;
        b *= 2;
        fb = log(fmax(contact_restitution_of_zeta(b, p), 1e-300)) - target;
    }
    for (int it = 0; it < 100 && fabs(b - a) > 1e-12 * b; it++) {
        double z = (a * fb - b * fa) / (fb - fa);
        double fz = log(fmax(contact_restitution_of_zeta(z, p), 1e-300))
                    - target;
        if (fabs(fz) < 1e-11)
            return z;
        if (fz * fb < 0)
            a = b, fa = fb;
        else
            fa *= 0.5;   /* Illinois: the retained end point is halved */
        b = z, fb = fz;
    }
    return 0.5 * (a + b);
}

static double zeta_restitution(double e, double p)
{
    return contact_zeta_of_restitution(e, p);
}

static void eval_restitution(const struct contact_coeffs *c,
                             const struct contact_geom *g, double kn,
                             double kt, double *eta_n, double *eta_t)
{
    *eta_n = 2.0 * c->zeta * sqrt(kn * g->mstar);
    *eta_t = 2.0 * c->zeta * sqrt(kt * g->mstar);
}

const struct contact_damping_ops contact_damping_restitution = {
    .name = "restitution",
    .reference = "exact e for linear and Hertz (Antypov and Elliott 2011; "
                 "doc/theory.md A0-22)",
    .zeta = zeta_restitution,
    .eval = eval_restitution,
};
