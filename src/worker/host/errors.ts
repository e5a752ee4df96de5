// Engine errors as the element layer reports them: the body or link key, the field at fault and the message.
import type { HostError } from '../protocol.js';

/** "radius must be > 0, got -1" → "radius"; "mass / 16 particles must …" (a builder's share of its mass) → "mass". */
function fieldOf(message: string): string {
  const m = /^([A-Za-z][\w.]*?)(?:\[\d+\])?(?:\.[xy])?(?: \/ \d+ particles)? must/.exec(message);
  return m ? m[1] : '';
}

export function errorOf(key: number, error: unknown): HostError {
  const message = error instanceof Error ? error.message : String(error);
  return { key, field: fieldOf(message), message };
}
