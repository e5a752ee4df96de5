// Served with COOP/COEP (cross-origin isolated): frames travel in a SharedArrayBuffer triple buffer.
import { transportSuite } from './transport-suite.js';

transportSuite('shared');
