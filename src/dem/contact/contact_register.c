/*
 * contact_register.c — the only lists to edit when a contact sub-model is
 * added (doc/design.md C3). The first entry is not necessarily the default:
 * the defaults are set in src/dem/dem_case.c.
 */
#include <stddef.h>

#include "dem/contact/contact.h"

const struct contact_normal_ops *const contact_normal_table[] = {
    &contact_normal_hertz, &contact_normal_linear, NULL};
const struct contact_damping_ops *const contact_damping_table[] = {
    &contact_damping_restitution, &contact_damping_xie2025,
    &contact_damping_tsuji, &contact_damping_restitution_constant,
    &contact_damping_none, NULL};
const struct contact_tangential_ops *const contact_tangential_table[] = {
    &contact_tangential_coulomb, &contact_tangential_none, NULL};
const struct contact_rolling_ops *const contact_rolling_table[] = {
    &contact_rolling_none, &contact_rolling_constant_torque,
    &contact_rolling_viscous, NULL};
const struct contact_twisting_ops *const contact_twisting_table[] = {
    &contact_twisting_none, &contact_twisting_viscous, NULL};
const struct contact_stiffness_ops *const contact_stiffness_table[] = {
    &contact_stiffness_mindlin, &contact_stiffness_xie2025, NULL};
