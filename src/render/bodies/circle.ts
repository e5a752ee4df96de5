// A ball: a disc of the topology's radius around its particle (drawn with the shapes of its style). A lone particle
// has no rotation to show with a spoke.
import { shape } from './painter.js';

export const circle = shape;
