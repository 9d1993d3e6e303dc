// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
// The RDC-1's display, live: rectangles of changed pixels arrive over a
// WebSocket as zlib-compressed RGBA and are drawn in the order they came;
// status messages (JSON) fill the table beside the picture.
'use strict';

const screen = document.getElementById('screen');
const ctx = screen.getContext('2d', { alpha: false });
const RECT_TYPE = 1;
const RECT_HDR = 20;
const PINS = ['TE', 'IRQ', 'RESET_N', 'BL_EN'];
const IRQS = ['VBLANK', 'LINE', 'FENCE', 'FIFO_LOW', 'ERROR'];
let chain = Promise.resolve();
let retry = 500;

function text(id, s) {
	document.getElementById(id).textContent = s;
}

function bits(id, names, v) {
	const el = document.getElementById(id);

	el.replaceChildren();
	names.forEach((n, i) => {
		const s = document.createElement('span');

		s.className = (v >> i) & 1 ? 'pin on' : 'pin';
		s.textContent = n;
		el.appendChild(s);
	});
}

async function rect(buf) {
	const v = new DataView(buf);

	if (buf.byteLength < RECT_HDR || v.getUint32(0, true) !== RECT_TYPE)
		return;
	const x = v.getUint32(4, true), y = v.getUint32(8, true);
	const w = v.getUint32(12, true), h = v.getUint32(16, true);
	const z = new Blob([new Uint8Array(buf, RECT_HDR)]).stream()
		.pipeThrough(new DecompressionStream('deflate'));
	const px = new Uint8ClampedArray(await new Response(z).arrayBuffer());

	if (!w || !h || px.length !== w * h * 4)
		throw new Error('bad rectangle');
	ctx.putImageData(new ImageData(px, w, h), x, y);
}

function status(s) {
	if (screen.width !== s.width || screen.height !== s.height) {
		screen.width = s.width;
		screen.height = s.height;
	}
	let mode = s.width + 'x' + s.height;
	if (s.format)
		mode += ' ' + s.format;
	if (s.interval[0] && s.interval[1])
		mode += ' @ ' + (s.interval[1] / s.interval[0]).toFixed(2) +
			' Hz';
	text('mode', mode);
	text('seq', String(s.seq));
	if (s.time !== undefined && s.core_hz)
		text('time', (s.time / s.core_hz).toFixed(6) + ' s (' +
		     s.time + ' cycles)');
	if (s.pins !== undefined)
		bits('pins', PINS, s.pins);
	if (s.irq_status !== undefined)
		bits('irq', IRQS, s.irq_status);
	// everything up to this frame has been drawn (tests read this)
	document.body.dataset.seq = String(s.seq);
}

function connect() {
	const token = new URLSearchParams(location.hash.slice(1)).get('token');
	const ws = new WebSocket((location.protocol === 'https:' ? 'wss://' :
				  'ws://') + location.host + '/ws');

	ws.binaryType = 'arraybuffer';
	ws.onopen = () => {
		retry = 500;
		ws.send(token || '');
		text('conn', 'open');
	};
	ws.onmessage = (ev) => {
		chain = chain.then(() => typeof ev.data === 'string' ?
			status(JSON.parse(ev.data)) : rect(ev.data))
			.catch((e) => { text('conn', 'error: ' + e.message);
					ws.close(); });
	};
	ws.onclose = (ev) => {
		if (ev.code === 4001) {
			text('conn', 'refused: wrong or missing token ' +
			     '(open the page as /#token=...)');
			return;
		}
		text('conn', 'closed (' + ev.code + '), retrying');
		setTimeout(connect, retry);
		retry = Math.min(retry * 2, 8000);
	};
}

connect();
