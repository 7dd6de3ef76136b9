// Presentation mode: full screen, large type, the form folded away.
import { $ } from '../dom.js';
import { presentPlots } from '../plots.js';
import { registerView } from '../views.js';

function present(on) {
  document.body.classList.toggle('presenting', on);
  presentPlots(on);
  $('present').setAttribute('aria-pressed', String(on));
  $('present').textContent = on ? 'Leave presentation' : 'Presentation mode';
  if (on && document.documentElement.requestFullscreen && !document.fullscreenElement) document.documentElement.requestFullscreen().catch(() => {});
  if (!on && document.fullscreenElement) document.exitFullscreen().catch(() => {});
}

registerView({
  id: 'present',
  init() {
    $('present').addEventListener('click', () => present(!document.body.classList.contains('presenting')));
    document.addEventListener('fullscreenchange', () => { if (!document.fullscreenElement && document.body.classList.contains('presenting')) present(false); });
  },
});
