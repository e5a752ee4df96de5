// A soft body: the closed outline of its ring (the topology's `ring`; a springs model's hub is not drawn).
import { shape } from './painter.js';

export const softbody = shape;
