/*
 * soil_dict.c — constant/soilProperties: the soil model and its
 * parameters, with the defaults of doc/theory.md K0-03 ... K0-09.
 *
 *   soilModel       solid;    // solid (Kim eqs. 9-15) | liquid (a second
 *                             // fluid with its own viscosity) |
 *                             // viscoplastic (yield stress, K.6)
 *   rho             1900;     // [kg/m^3]
 *   mu              0.577;    // friction coefficient (K0-09)
 *   columnHalfWidth 0.5;      // b of eq. (13) [l0] (K0-03)
 *   frictionWeight  none;     // none | kernel (K0-04)
 *   frictionCap     no;       // (K0-05)
 *   frictionLoad    withoutFriction; // | total (K0-10)
 *   dragCoefficient 1;        // C_D of K.1 (K0-06, K0-09)
 *   dragReaction    yes;      // the drag's reaction on the fluid
 *   nu              1e-3;     // [m^2/s] liquid model (K0-09)
 *   cohesion        0;        // [Pa] viscoplastic model (K.6)
 *   maxViscosity    1000;     // [m^2/s] viscoplastic model (K0-11)
 */
#include "core/dict.h"
#include "core/error.h"
#include "core/select.h"
#include "mps/soil/soil.h"

static const struct model_head model_solid = {
    "solid", "Kim eqs. 9-15, doc/theory.md K.2-K.4" };
static const struct model_head model_liquid = {
    "liquid", "Kim's liquid-soil model: a second fluid" };
static const struct model_head model_viscoplastic = {
    "viscoplastic", "Drucker-Prager yield stress c + mu p as an implicit "
    "viscosity, doc/theory.md K.6" };
const struct model_head *const soil_model_table[] = {
    &model_solid, &model_liquid, &model_viscoplastic, NULL };

static const struct model_head weight_none = {
    "none", "Kim eqs. 10-11 as printed (doc/theory.md K0-04)" };
static const struct model_head weight_kernel = {
    "kernel", "pair terms times d w/n0 (doc/theory.md K0-04)" };
const struct model_head *const soil_friction_weight_table[] = {
    &weight_none, &weight_kernel, NULL };

static const struct model_head load_without = {
    "withoutFriction", "a of eq. 10: the last step's acceleration less the "
    "friction's own part (doc/theory.md K0-10)" };
static const struct model_head load_total = {
    "total", "a of eq. 10: the last step's whole acceleration, friction "
    "included (doc/theory.md K0-10)" };
const struct model_head *const soil_friction_load_table[] = {
    &load_without, &load_total, NULL };

#define TABLE(t) ((const void *const *)(t))

static const int DIM_RHO[7] = { 1, -3, 0, 0, 0, 0, 0 };
static const int DIM_NU[7] = { 0, 2, -1, 0, 0, 0, 0 };
static const int DIM_PA[7] = { 1, -1, -2, 0, 0, 0, 0 };

int soil_props_read(const struct dict *d, struct soil_props *p)
{
    TRY(model_select_index(d, "soilModel", "soil model",
                           TABLE(soil_model_table), "solid", &p->model));
    TRY(dict_get_scalar_dim(d, "rho", DIM_RHO, &p->rho));
    TRY(dict_range(d, "rho", p->rho, 0, 1e5, 1));
    TRY(dict_get_scalar_or(d, "mu", 0.577, &p->mu));
    TRY(dict_range(d, "mu", p->mu, 0, 10, 0));
    TRY(dict_get_scalar_or(d, "columnHalfWidth", 0.5, &p->column_half_width));
    TRY(dict_range(d, "columnHalfWidth", p->column_half_width, 0, 100, 1));
    TRY(model_select_index(d, "frictionWeight", "friction weight",
                           TABLE(soil_friction_weight_table), "none",
                           &p->kernel_weight));
    TRY(dict_get_bool_or(d, "frictionCap", 0, &p->cap));
    TRY(model_select_index(d, "frictionLoad", "friction load",
                           TABLE(soil_friction_load_table), "withoutFriction",
                           &p->load_total));
    TRY(dict_get_scalar_or(d, "dragCoefficient", 1.0, &p->cd));
    TRY(dict_range(d, "dragCoefficient", p->cd, 0, 1e3, 0));
    TRY(dict_get_bool_or(d, "dragReaction", 1, &p->drag_reaction));
    TRY(dict_get_scalar_dim_or(d, "nu", DIM_NU, 1e-3, &p->nu));
    TRY(dict_range(d, "nu", p->nu, 0, 1e3, 1));
    TRY(dict_get_scalar_dim_or(d, "cohesion", DIM_PA, 0.0, &p->cohesion));
    TRY(dict_range(d, "cohesion", p->cohesion, 0, 1e9, 0));
    TRY(dict_get_scalar_dim_or(d, "maxViscosity", DIM_NU, 1000.0, &p->nu_max));
    TRY(dict_range(d, "maxViscosity", p->nu_max, 0, 1e6, 1));
    return SIM_OK;
}
