/* whirl/rotor.h — the rotor module (libwhirl-rotor, pkg-config whirl-rotor):
 * models of nonlinear rotors built on the generic library (whirl/whirl.h)
 * through its public API only.  Today: the rigid rotor on two short
 * squeeze-film dampers of the paper (sfd.h: the force, both frames, eq. 15;
 * sfd_dynamics.h: time-domain attractors and basins; sfd_periodic.h:
 * periodic responses and the nonsynchronous branch; sfd_region.h: the isola
 * merge curve and region of Fig. 18) and the Jeffcott rotor on the same
 * dampers (whirl_rotor_jeffcott), registered for `whirl run` by
 * whirl_rotor_register_models; finite-element rotors read from a rotor file
 * (fe.h) and their linear analyses (fe_linear.h: modes, Campbell diagram,
 * critical speeds, unbalance response).
 * SPDX-License-Identifier: BSD-3-Clause */
#ifndef WHIRL_ROTOR_H
#define WHIRL_ROTOR_H

#include <whirl/whirl.h>
#include <whirl/rotor/sfd.h>
#include <whirl/rotor/sfd_dynamics.h>
#include <whirl/rotor/sfd_periodic.h>
#include <whirl/rotor/sfd_region.h>
#include <whirl/rotor/fe.h>
#include <whirl/rotor/fe_linear.h>
#include <whirl/rotor/fe_hbm.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The Jeffcott rotor (a disc on a flexible massless shaft) on two short
 * pi-film SFDs, fixed frame, forced: x = (yd, zd, yj, zj, dyd, dzd, dyj,
 * dzj), p = (Omega, lambda, delta, zeta, alpha, kappa) (doc/jeffcott-model.md).
 * kappa -> infinity is the rigid rotor of whirl_sfd_fixed. */
WHIRL_API const whirl_model *whirl_rotor_jeffcott(void);

/* Add the rotor module's models to a registry of `whirl run` models:
 * "sfd" (the SFD rigid rotor in the fixed frame, forced at Omega),
 * "sfd-rotating" (the same in the rotating frame, where circular orbits are
 * equilibria) and "jeffcott" (whirl_rotor_jeffcott).  WHIRL_OK, or an error status with the reason in msg. */
WHIRL_API int whirl_rotor_register_models(whirl_model_registry *reg, char *msg,
                                          size_t len);

#ifdef __cplusplus
}
#endif
#endif
