// A box: the closed outline of its particles.
import { shape } from './painter.js';

export const box = shape;
