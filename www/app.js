// Main thread: the form and the results. The simulation runs in worker.js, never here.
const $ = (id) => document.getElementById(id);
const SHOWN = [
  ['ship_speed_kn', 'ship speed [kn]'],
  ['prop_rpm', 'propeller speed [rpm]'],
  ['turbine_speed_pu', 'turbine speed [pu]'],
  ['bus_voltage_pu', 'bus voltage [pu]'],
  ['im_power_pu', 'motor power [pu of 38 MW]'],
  ['thrust_kn', 'thrust [kN]'],
];
let worker = null;
let presets = {};

function status(text, isError = false) {
  $('status').textContent = text;
  $('status').className = isError ? 'error' : '';
}

function startWorker() {
  worker = new Worker('worker.js', { type: 'module' });
  worker.onmessage = (ev) => {
    const m = ev.data;
    if (m.type === 'ready') {
      presets = m.presets;
      $('preset').replaceChildren(...Object.keys(presets).map((n) => new Option(n, n)));
      $('preset').onchange();
      status('Ready.');
    } else if (m.type === 'progress') {
      $('progress').value = m.fraction;
    } else if (m.type === 'done') {
      $('run').disabled = false;
      $('cancel').disabled = true;
      $('progress').value = 1;
      showSummary(JSON.parse(m.summary));
      status(`Done: ${m.simulated_s} s simulated in ${(m.wall_ms / 1000).toFixed(2)} s.`);
    } else if (m.type === 'error') {
      $('run').disabled = false;
      $('cancel').disabled = true;
      status(m.message, true);
    }
  };
  worker.onerror = (e) => status(`Worker failed: ${e.message}`, true);
}

function showSummary(s) {
  const body = $('summary').querySelector('tbody');
  body.replaceChildren(...SHOWN.map(([key, label]) => {
    const v = s.signals[key];
    const tr = document.createElement('tr');
    const cells = [label, v.final, v.min, v.max].map((x, i) => {
      const td = document.createElement(i === 0 ? 'th' : 'td');
      td.textContent = i === 0 ? x : Number(x).toPrecision(4);
      return td;
    });
    tr.append(...cells);
    return tr;
  }));
  $('summary').hidden = false;
}

$('preset').onchange = () => {
  const sc = presets[$('preset').value];
  $('description').textContent = sc ? JSON.parse(sc).description : '';
};
$('run').onclick = () => {
  $('run').disabled = true;
  $('cancel').disabled = false;
  $('progress').value = 0;
  status('Running...');
  worker.postMessage({ type: 'run', scenario: presets[$('preset').value] });
};
$('cancel').onclick = () => {
  // Ending the worker is the only cancel that always works; a fresh one takes its place.
  worker.terminate();
  $('run').disabled = false;
  $('cancel').disabled = true;
  status('Cancelled.');
  startWorker();
};
startWorker();
