// Snapshot and restore of the whole host (world, records, params), and the frame overlay of a restart: the snapshot
// holds the full state (constraints, contacts, sleep) as of up to a second ago; the page's newest frame holds where
// every particle was drawn last. Laying the frame over the restored world resumes from what the user saw.
import type { WorldSnapshot } from '../../engine/index.js';
import { ParticleFlag, type ParticleStore } from '../../engine/particles.js';
import { POSE, type FramePatch, type HostSnapshot } from '../protocol.js';
import type { Bindings } from './bindings.js';
import { copyParams, type HostSettings } from './settings.js';

/** `topology`: the version of the topology in force (-1 while a change is unpublished), to match frames against. */
export function takeSnapshot(b: Bindings, settings: HostSettings, topology: number): HostSnapshot {
  return { world: b.world.snapshot(), ...b.snapshot(), params: copyParams(settings.params), topology };
}

/** Puts the snapshot back; with a frame of the snapshot's topology, the frame's positions and velocities on top. */
export function restoreSnapshot(b: Bindings, settings: HostSettings, s: HostSnapshot, frame?: FramePatch | null): void {
  // The world first: it refuses a bad snapshot before anything has changed.
  b.world.restore(s.world as WorldSnapshot);
  settings.params = copyParams(s.params);
  b.restore(s);
  if (frame) overlay(b, s, frame);
}

/** Whether row i moves (dynamic, or kinematic: moved by its velocities); static and pinned rows stay put. */
function moves(p: ParticleStore, i: number): boolean {
  return p.alive[i] === 1 && (p.invMass[i] > 0 || (p.flags[i] & ParticleFlag.Kinematic) !== 0);
}

/**
 * Moves the particles to where the frame drew them and turns rigid bodies to the frame's angles (velocities and
 * angular velocities from the two newest frames, else the snapshot's). Only when the frame has the snapshot's
 * topology (same particles in the same slots, same bodies in the same order) and is not older than it.
 */
function overlay(b: Bindings, s: HostSnapshot, f: FramePatch): void {
  const w = b.world;
  const p = w.particles;
  const n = p.count;
  if (s.topology === undefined || s.topology < 0 || f.topology !== s.topology || f.positions.length !== 2 * n) return;
  if (f.stepCount < w.stepCount || (f.velocities && f.velocities.length !== 2 * n)) return;
  for (let i = 0; i < n; i++) {
    if (!moves(p, i)) continue;
    const x = f.positions[2 * i];
    const y = f.positions[2 * i + 1];
    if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
    p.x[i] = p.px[i] = p.qx[i] = p.sx[i] = x;
    p.y[i] = p.py[i] = p.qy[i] = p.sy[i] = y;
    if (f.velocities && Number.isFinite(f.velocities[2 * i]) && Number.isFinite(f.velocities[2 * i + 1])) {
      p.vx[i] = f.velocities[2 * i];
      p.vy[i] = f.velocities[2 * i + 1];
    }
  }
  const bodies = b.built();
  if (f.poses && f.poses.length === POSE * bodies.length) {
    bodies.forEach((r, k) => {
      const i = r.indices[0];
      if (!r.rigid || !moves(p, i)) return;
      const angle = f.poses![POSE * k + 2];
      if (!Number.isFinite(angle)) return;
      p.angle[i] = p.pangle[i] = p.qangle[i] = p.sangle[i] = angle;
      p.rc[i] = Math.cos(angle);
      p.rs[i] = Math.sin(angle);
      const spin = f.spins?.length === bodies.length ? f.spins[k] : Number.NaN;
      if (Number.isFinite(spin)) p.omega[i] = spin;
    });
  }
  w.stepCount = f.stepCount;
  w.time = f.time;
  // Bodies asleep in the snapshot may have been moving in the frame.
  w.wakeAll();
}
