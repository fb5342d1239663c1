// afford view: plays a recording (serve/recording_view.h, fetched as
// /recording.json) in the page of afford serve: play, pause, scrub, and
// jump to each event of the list. The page's own functions draw it.
const $ = (id) => document.getElementById(id);

// The last state at or before t (s); states are in time order.
function stateAt(states, t) {
  let lo = 0, hi = states.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (states[mid].t <= t) lo = mid; else hi = mid - 1;
  }
  return states[lo];
}

export async function play(page) {
  const response = await fetch('/recording.json');
  if (!response.ok) throw new Error(`/recording.json: HTTP ${response.status}`);
  const rec = await response.json();
  if (rec.states.length === 0) throw new Error('the recording has no frames');
  page.buildScene(rec.scene);
  $('trial').textContent = `recording ${rec.file}: session ${rec.session}, ${rec.summary}` +
    (rec.identical ? '' : ' (the re-run differs from the recording: afford replay says where)');
  $('player').hidden = false;

  const end = rec.states[rec.states.length - 1].t;
  const scrub = $('scrub');
  scrub.max = end;
  let t = rec.states[0].t, playing = true, last = null;
  const show = () => {
    page.applyState(stateAt(rec.states, t));
    scrub.value = t;
    $('clock').textContent = `${t.toFixed(3)} s of ${end.toFixed(3)} s`;
    $('play').textContent = playing ? 'pause' : 'play';
  };
  const jump = (to) => { t = Math.max(0, Math.min(end, to)); show(); };

  // The whole list at once, each entry a link to its moment.
  for (const e of rec.events) {
    const li = page.addEvent(e);
    if (!li) continue;
    li.classList.add('jump');
    li.title = 'jump here';
    li.onclick = () => { playing = false; jump(e.t); };
  }
  $('play').onclick = () => {
    if (t >= end) t = 0;
    playing = !playing;
    show();
  };
  scrub.oninput = () => { playing = false; jump(Number(scrub.value)); };
  window.addEventListener('keydown', (e) => {
    if (e.key === ' ') { playing = !playing; show(); e.preventDefault(); }
  });

  // Session time goes at wall-clock pace while playing.
  const tick = (now) => {
    if (playing && last !== null) {
      t = Math.min(end, t + (now - last) / 1000);
      if (t >= end) playing = false;
      show();
    }
    last = now;
    requestAnimationFrame(tick);
  };
  show();
  requestAnimationFrame(tick);
}
