/*
 * mps_dict.c — MPS settings from the case dictionaries (keys documented in
 * applications/solvers/mpsFluid/mpsFluid.reference):
 *
 *   constant/transportProperties  rho [kg/m^3], nu [m^2/s]
 *   constant/g                    value (gx gy gz) [m/s^2] (or g (...))
 *   system/mpsSchemes             kernel, reNumberDensity, reGradient,
 *                                 reLaplacian [dp], pressureGradient,
 *                                 porousLaplacian,
 *                                 sourceMix (gamma), freeSurface {...},
 *                                 collision, shifting (+ <name>Coeffs),
 *                                 dummyPressure, renumberInterval,
 *                                 neighbourSkin, neighbourDistances
 *   system/mpsSolution            maxEscapeFraction (PPE {...} is read by
 *                                 linsolve_create)
 */
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/select.h"
#include "mps/kernel/kernel.h"
#include "mps/mps.h"
#include "mps/soil/soil.h"
#include "mps/stabiliser/stabiliser.h"

/* The choices without ops (core/select.h), in the order of their enums
 * in mps.h. */
static const struct model_head grad_symmetric = {
    "symmetric", "Xie et al. 2025 eq. 8, p_i + p_j" };
static const struct model_head grad_minimum = {
    "minimum", "Koshizuka & Oka 1996 eq. 11, p_j - p_min" };
static const struct model_head grad_corrected = {
    "corrected", "Khayyer & Gotoh 2011 corrective matrix" };
static const struct model_head *const gradient_table[] = {
    &grad_symmetric, &grad_minimum, &grad_corrected, NULL };

static const struct model_head porous_neighbour = {
    "neighbour", "Xie et al. 2025 eq. 10, weight 1/eps_j" };
static const struct model_head porous_symmetric = {
    "symmetric", "doc/theory.md A.4, weight 2/(eps_i + eps_j)" };
static const struct model_head *const porous_table[] = {
    &porous_neighbour, &porous_symmetric, NULL };

static const struct model_head dummy_wall = {
    "nearestWall", "doc/theory.md A.9" };
static const struct model_head dummy_zero = {
    "zero", "Koshizuka et al. 1998" };
static const struct model_head dummy_extrapolated = {
    "extrapolated", "Adami, Hu & Adams 2012 eq. 27" };
static const struct model_head *const dummy_table[] = {
    &dummy_wall, &dummy_zero, &dummy_extrapolated, NULL };

static const struct model_head dist_stored = {
    "stored", "8 bytes per pair, read where used" };
static const struct model_head dist_measured = {
    "measured", "from the list's positions where used: less memory" };
static const struct model_head *const dist_table[] = {
    &dist_stored, &dist_measured, NULL };

static const struct model_head fs_zero = { "zero", "doc/theory.md A.4" };
static const struct model_head fs_extrapolated = {
    "extrapolated", "Gibou et al. 2002 eq. 8, p = 0 dp/2 outside" };
static const struct model_head *const fs_pressure_table[] = {
    &fs_zero, &fs_extrapolated, NULL };

#define TABLE(t) ((const void *const *)(t))

const struct model_choice mps_choices[] = {
    { "system/mpsSchemes", "kernel", TABLE(mps_kernel_table) },
    { "system/mpsSchemes", "pressureGradient", TABLE(gradient_table) },
    { "system/mpsSchemes", "porousLaplacian", TABLE(porous_table) },
    { "system/mpsSchemes", "freeSurface/pressure", TABLE(fs_pressure_table) },
    { "system/mpsSchemes", "collision", TABLE(mps_collision_table) },
    { "system/mpsSchemes", "shifting", TABLE(mps_shifting_table) },
    { "system/mpsSchemes", "dummyPressure", TABLE(dummy_table) },
    { "system/mpsSchemes", "neighbourDistances", TABLE(dist_table) },
    { "constant/soilProperties", "soilModel", TABLE(soil_model_table) },
    { "constant/soilProperties", "frictionWeight",
      TABLE(soil_friction_weight_table) },
    { "constant/soilProperties", "frictionLoad",
      TABLE(soil_friction_load_table) },
    { NULL, NULL, NULL }
};

static const int DIM_RHO[7] = { 1, -3, 0, 0, 0, 0, 0 };
static const int DIM_NU[7] = { 0, 2, -1, 0, 0, 0, 0 };

static int read_physics(const struct dict *tp, const struct dict *gd,
                        struct mps_settings *S)
{
    TRY(dict_get_scalar_dim(tp, "rho", DIM_RHO, &S->rho));
    TRY(dict_range(tp, "rho", S->rho, 0, 1e6, 1));
    TRY(dict_get_scalar_dim(tp, "nu", DIM_NU, &S->nu));
    TRY(dict_range(tp, "nu", S->nu, 0, 1e3, 1));
    if (gd) {
        const char *key = dict_has(gd, "value") ? "value" : "g";
        TRY(dict_get_vector(gd, key, 3, S->g));
        if (dict_has(gd, "dimensions"))
            dict_mark_used(gd, "dimensions");
    }
    return SIM_OK;
}

static int read_radii(const struct dict *d, struct mps_settings *S)
{
    TRY(dict_get_scalar_or(d, "reNumberDensity", 2.1, &S->re_n));
    TRY(dict_get_scalar_or(d, "reGradient", S->re_n, &S->re_grad));
    TRY(dict_get_scalar_or(d, "reLaplacian", 3.1, &S->re_lap));
    TRY(dict_range(d, "reNumberDensity", S->re_n, 1.0, 10.0, 1));
    TRY(dict_range(d, "reGradient", S->re_grad, 1.0, 10.0, 1));
    TRY(dict_range(d, "reLaplacian", S->re_lap, 1.0, 10.0, 1));
    return SIM_OK;
}

static int read_free_surface(const struct dict *d, struct mps_settings *S)
{
    const struct dict *fs;
    TRY(dict_find_dict(d, "freeSurface", &fs));
    if (!fs)
        return SIM_OK;
    TRY(dict_get_scalar_or(fs, "beta", S->beta, &S->beta));
    TRY(dict_range(fs, "beta", S->beta, 0, 1, 1));
    TRY(dict_get_scalar_or(fs, "alpha", S->alpha, &S->alpha));
    TRY(dict_range(fs, "alpha", S->alpha, 0, 2, 1));
    TRY(dict_get_scalar_or(fs, "vectorDensityLimit", S->fs_n_max,
                           &S->fs_n_max));
    TRY(dict_range(fs, "vectorDensityLimit", S->fs_n_max, 0, 2, 1));
    TRY(model_select_index(fs, "pressure", "free-surface pressure",
                           TABLE(fs_pressure_table),
                           fs_pressure_table[S->fs_pressure]->name,
                           &S->fs_pressure));
    static const char *const sweeps[] = { "sequential", "simultaneous",
                                          NULL };
    TRY(dict_get_word_or(fs, "sweep", sweeps, 0, &S->fs_simultaneous));
    TRY(dict_get_scalar_or(fs, "betaPorous", S->beta_porous,
                           &S->beta_porous));
    TRY(dict_range(fs, "betaPorous", S->beta_porous, 0, 1, 1));
    return SIM_OK;
}

static int read_stabilisers(const struct dict *d, struct mps_settings *S)
{
    const void *m;
    const struct dict *c;
    TRY(model_select(d, "collision", "collision model",
                     TABLE(mps_collision_table), "none", &m));
    S->collision = m;
    TRY(dict_find_dict(d, "lee2011Coeffs", &c));
    if (c) {
        TRY(dict_get_scalar_or(c, "distance", S->collision_ratio,
                               &S->collision_ratio));
        TRY(dict_range(c, "distance", S->collision_ratio, 0, 1, 1));
        TRY(dict_get_scalar_or(c, "restitution", S->collision_restitution,
                               &S->collision_restitution));
        TRY(dict_range(c, "restitution", S->collision_restitution + 1, 0, 2,
                       1));
    }
    TRY(model_select(d, "shifting", "particle shifting",
                     TABLE(mps_shifting_table), "none", &m));
    S->shifting = m;
    TRY(dict_find_dict(d, S->shifting == &mps_shifting_lind2012
                           ? "lind2012Coeffs" : "xu2009Coeffs", &c));
    if (c) {
        TRY(dict_get_scalar_or(c, "coefficient", S->shifting_coeff,
                               &S->shifting_coeff));
        TRY(dict_range(c, "coefficient", S->shifting_coeff, 0, 1, 1));
    }
    return SIM_OK;
}

static int read_schemes(const struct dict *d, struct mps_settings *S)
{
    const void *k;
    TRY(model_select(d, "kernel", "MPS kernel", TABLE(mps_kernel_table),
                     "zhang2014", &k));
    S->kernel = k;
    TRY(read_radii(d, S));
    TRY(model_select_index(d, "pressureGradient", "pressure gradient",
                           TABLE(gradient_table), "symmetric", &S->gradient));
    TRY(model_select_index(d, "porousLaplacian", "porous Laplacian",
                           TABLE(porous_table), "neighbour",
                           &S->porous_symmetric));
    TRY(dict_get_bool_or(d, "predictor", S->predictor, &S->predictor));
    TRY(dict_get_bool_or(d, "clipNegativePressure", S->clip_negative,
                         &S->clip_negative));
    TRY(dict_get_scalar_or(d, "sourceMix", S->gamma, &S->gamma));
    if (!(S->gamma >= 0 && S->gamma <= 1))
        return dict_error(d, "sourceMix", SIM_ERR_DICT, "sourceMix (gamma "
                          "of eq. 12) must lie in [0, 1], not %g", S->gamma);
    TRY(read_free_surface(d, S));
    TRY(read_stabilisers(d, S));
    TRY(model_select_index(d, "dummyPressure", "dummy pressure",
                           TABLE(dummy_table), "nearestWall",
                           &S->dummy_pressure));
    long r;
    TRY(dict_get_label_or(d, "renumberInterval", S->renumber_interval, &r));
    if (r < 0 || r > 1000000)
        return dict_error(d, "renumberInterval", SIM_ERR_DICT,
                          "renumberInterval must be >= 0 (0 = never)");
    S->renumber_interval = (int)r;
    TRY(dict_get_scalar_or(d, "neighbourSkin", S->skin, &S->skin));
    if (!(S->skin >= 0 && S->skin <= 2))
        return dict_error(d, "neighbourSkin", SIM_ERR_DICT, "neighbourSkin "
                          "must lie in [0, 2] dp");
    TRY(model_select_index(d, "neighbourDistances", "neighbour distances",
                           TABLE(dist_table), "stored", &S->measure_r));
    return SIM_OK;
}

int mps_settings_read(const struct dict *transport, const struct dict *g,
                      const struct dict *schemes, const struct dict *solution,
                      struct mps_settings *S)
{
    mps_settings_default(S);
    TRY(read_physics(transport, g, S));
    TRY(read_schemes(schemes, S));
    if (solution) {
        TRY(dict_get_scalar_or(solution, "maxEscapeFraction",
                               S->max_escape_fraction,
                               &S->max_escape_fraction));
        TRY(dict_range(solution, "maxEscapeFraction", S->max_escape_fraction,
                       0, 1, 1));
    }
    return SIM_OK;
}
