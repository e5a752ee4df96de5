// A polygon: the closed outline of its particles.
import { shape } from './painter.js';

export const polygon = shape;
