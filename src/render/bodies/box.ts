// A box: a rigid body's outline at its pose, or (model 'particles') the closed outline of its particles.
import { shape } from './painter.js';

export const box = shape;
