// A gamepad (the browser's Gamepad API) drives the hand: the left stick
// pushed up squeezes the thumb (full up: the largest squeeze), A (button 0)
// grasps, B (button 1) releases; where the pad rumbles, it rumbles with
// the reaction the thumb feels (eq. 5), as force feedback.
let lastSqueeze = -1, lastButtons = [false, false], lastRumble = 0;

export function pollGamepad(state, maxSqueeze, send) {
  const pad = navigator.getGamepads ? Array.from(navigator.getGamepads()).find((p) => p) : null;
  if (!pad) return;
  const push = Math.max(0, -(pad.axes[1] || 0));
  const squeeze = push < 0.05 ? 0 : push * maxSqueeze;  // a dead zone: a stick at rest is not exactly 0
  if (Math.abs(squeeze - lastSqueeze) > 0.0005) {
    send({ type: 'thumb', squeeze });
    lastSqueeze = squeeze;
  }
  ['grasp', 'release'].forEach((type, i) => {
    const down = pad.buttons[i] ? pad.buttons[i].pressed : false;
    if (down && !lastButtons[i]) send({ type });
    lastButtons[i] = down;
  });
  const now = performance.now();
  if (pad.vibrationActuator && now - lastRumble > 100 && state.max_force > 0) {
    const strength = Math.min(1, state.reaction / state.max_force);
    if (strength > 0.01) pad.vibrationActuator.playEffect('dual-rumble', { duration: 120, strongMagnitude: strength, weakMagnitude: strength / 2 });
    lastRumble = now;
  }
}
