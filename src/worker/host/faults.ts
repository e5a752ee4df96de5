// Test faults (fault recovery tests): make the engine fail on purpose, as a crashed or hung worker would.
import type { DebugFault } from '../protocol.js';
import type { StepLoop } from './loop.js';

/** 'throw' arms the step loop to throw on its next tick; 'hang' blocks this thread (20 s at most). */
export function debugFault(fault: DebugFault, loop: StepLoop): void {
  if (fault === 'throw') loop.failNextTick = true;
  else if (fault === 'hang') {
    // After this call has answered: the next call gets no answer.
    setTimeout(() => {
      const until = performance.now() + 20000;
      while (performance.now() < until) {
        // busy: nothing else runs in this worker meanwhile
      }
    }, 0);
  }
}
