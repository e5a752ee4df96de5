// A polygon: a rigid body's outline (as described, a concave one too) at its pose, or (model 'particles') the closed
// outline of its particles.
import { shape } from './painter.js';

export const polygon = shape;
