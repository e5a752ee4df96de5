// Dev server config for experiment 2: like web-dev-server.config.js, but pages whose URL (or referrer) says
// "transfer" are served without COOP/COEP, so their scenes publish frames through transferred ArrayBuffers instead
// of the SharedArrayBuffer triple buffer.
import base, { crossOriginIsolation, jsToTs } from '../web-dev-server.config.js';

const transfer = (ctx) => /transfer/.test(ctx.url) || /transfer/.test(ctx.headers.referer ?? '');
export default { ...base, middleware: [crossOriginIsolation({ when: (ctx) => !transfer(ctx) }), jsToTs] };
