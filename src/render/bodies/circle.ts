// A ball: a rigid disc at its pose with a radius line along its angle, so its spin shows; or (model 'particles') a disc
// of the topology's radius around its one particle, which has no rotation to show.
import { shape } from './painter.js';

export const circle = shape;
