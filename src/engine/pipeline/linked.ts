import type { StepContext } from './context.js';

/**
 * Calls `visit` with particles that a distance, spring, angle or area constraint ties together (for an area, its first
 * particle with each other one): what joins bodies for sleeping, and what closes a body for free spin (spin.ts).
 */
export function eachLinkedPair(ctx: StepContext, visit: (i: number, j: number) => void): void {
  const { distances: d, springs: s, angles: g, areas: ar } = ctx.constraints;
  for (let r = 0; r < d.count; r++) visit(d.a[r], d.b[r]);
  for (let r = 0; r < s.count; r++) visit(s.a[r], s.b[r]);
  for (let r = 0; r < g.count; r++) {
    visit(g.a[r], g.b[r]);
    visit(g.b[r], g.c[r]);
  }
  for (let r = 0; r < ar.count; r++) for (let k = 1; k < ar.length[r]; k++) visit(ar.pool[ar.start[r]], ar.pool[ar.start[r] + k]);
}
