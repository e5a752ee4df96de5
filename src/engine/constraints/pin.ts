import { Table } from '../table.js';
import type { ParticleStore } from '../particles.js';

/**
 * Pins a particle to a world point. A rigid pin (compliance 0) makes the particle kinematic: its inverse mass is
 * parked in `savedInvMass` and it is placed exactly on the target every substep, so nothing can drag it away.
 * A soft pin (compliance > 0) is an XPBD spring of rest length 0 towards the target.
 */
export class PinConstraints extends Table {
  readonly columns = ['p', 'tx', 'ty', 'compliance', 'lambdaX', 'lambdaY', 'savedInvMass', 'slot'] as const;
  p = new Int32Array(16);
  tx = new Float64Array(16);
  ty = new Float64Array(16);
  compliance = new Float64Array(16);
  lambdaX = new Float64Array(16);
  lambdaY = new Float64Array(16);
  savedInvMass = new Float64Array(16);
  slot = new Int32Array(16);
}

/** Rigid pins: called once per substep right after integration, so moving targets carry their particle along. */
export function placeRigidPins(c: PinConstraints, p: ParticleStore): void {
  const { x, y } = p;
  for (let i = 0, n = c.count; i < n; i++) {
    if (c.compliance[i] !== 0) continue;
    x[c.p[i]] = c.tx[i];
    y[c.p[i]] = c.ty[i];
  }
}

export function solveSoftPins(c: PinConstraints, p: ParticleStore, h2: number): void {
  const { x, y, invMass } = p;
  for (let i = 0, n = c.count; i < n; i++) {
    if (c.compliance[i] === 0) continue;
    const k = c.p[i];
    const w = invMass[k];
    if (w === 0) continue;
    const alpha = c.compliance[i] / h2;
    // The two axes are independent constraints with the same compliance.
    const dlx = (-(x[k] - c.tx[i]) - alpha * c.lambdaX[i]) / (w + alpha);
    const dly = (-(y[k] - c.ty[i]) - alpha * c.lambdaY[i]) / (w + alpha);
    c.lambdaX[i] += dlx;
    c.lambdaY[i] += dly;
    x[k] += w * dlx;
    y[k] += w * dly;
  }
}
