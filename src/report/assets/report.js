// The report page's script (sunglint compare): draws the charts with Chart.js from the
// results embedded in the page, and drives the reference/method sliders. Plain ES2017,
// no modules, so the page works from file://.
(function () {
  'use strict';
  var results = JSON.parse(document.getElementById('sg-results').textContent);
  var palette = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b', '#e377c2',
    '#7f7f7f', '#bcbd22', '#17becf'];
  var methods = results.settings.methods;
  var scenes = results.scenes;

  function colour(k) { return palette[k % palette.length]; }
  function slug(s) {
    var out = s.toLowerCase().replace(/[^a-z0-9]+/g, '-').slice(0, 48).replace(/^-+|-+$/g, '');
    return out || 'method';
  }
  function variant(scene, label) {
    for (var k = 0; k < scene.methods.length; ++k) {
      if (scene.methods[k].label === label) return scene.methods[k];
    }
    return null;
  }
  function metric(scene, label, region, key) {
    var v = variant(scene, label);
    var x = v ? v.regions[region][key] : null;
    return typeof x === 'number' ? x : null;
  }
  var common = { animation: false, responsive: true, maintainAspectRatio: false };

  // One bar per method and scene.
  function bars(id, title, value, yTitle) {
    var canvas = document.getElementById(id);
    if (!canvas) return;
    new Chart(canvas, {
      type: 'bar',
      data: {
        labels: scenes.map(function (s) { return s.name; }),
        datasets: methods.map(function (m, k) {
          return { label: m, backgroundColor: colour(k),
            data: scenes.map(function (s) { return value(s, m); }) };
        })
      },
      options: Object.assign({}, common, {
        plugins: { title: { display: true, text: title } },
        scales: { y: { beginAtZero: true, title: { display: true, text: yTitle } } }
      })
    });
  }
  bars('chart-rmse', 'RMSE against the reference (whole image)',
    function (s, m) { return metric(s, m, 'image', 'rmse'); }, 'RMSE');
  bars('chart-temporal', 'Temporal error (frame-to-frame change the reference lacks)',
    function (s, m) { return metric(s, m, 'image', 'temporal_error'); }, 'temporal error');
  bars('chart-time', 'Time per frame', function (s, m) {
    var v = variant(s, m);
    return v ? v.ms_per_frame : null;
  }, 'ms');

  // Near and far halves of the water: one group per scene and half.
  (function () {
    var canvas = document.getElementById('chart-nearfar');
    if (!canvas) return;
    var labels = [], pairs = [];
    scenes.forEach(function (s) {
      ['near', 'far'].forEach(function (r) { labels.push(s.name + ' ' + r); pairs.push([s, r]); });
    });
    new Chart(canvas, {
      type: 'bar',
      data: {
        labels: labels,
        datasets: methods.map(function (m, k) {
          return { label: m, backgroundColor: colour(k),
            data: pairs.map(function (p) { return metric(p[0], m, p[1], 'rmse'); }) };
        })
      },
      options: Object.assign({}, common, {
        plugins: { title: { display: true, text: 'RMSE in the near and far halves of the water' } },
        scales: { y: { beginAtZero: true, title: { display: true, text: 'RMSE' } } }
      })
    });
  })();

  // Quality-cost: the supersampling budgets as a curve, each method as a point.
  scenes.forEach(function (s) {
    var canvas = document.getElementById('chart-cost-' + slug(s.name));
    if (!canvas) return;
    var positive = function (p) { return p.x > 0 && p.y > 0; };
    var datasets = [{
      label: 'supersample (budgets)', showLine: true, borderColor: '#444', backgroundColor: '#444',
      data: s.budgets.map(function (b) {
        return { x: b.ms_per_frame, y: b.regions.image.rmse, spp: b.spp, label: b.label };
      }).filter(positive)
    }];
    s.methods.forEach(function (m, k) {
      var target = results.settings.equal_cost_target === m.label;
      datasets.push({ label: m.label, backgroundColor: colour(k), borderColor: colour(k),
        pointRadius: target ? 8 : 6, pointStyle: target ? 'star' : 'rectRot',
        data: [{ x: m.ms_per_frame, y: m.regions.image.rmse, label: m.label }].filter(positive) });
    });
    new Chart(canvas, {
      type: 'scatter',
      data: { datasets: datasets },
      options: Object.assign({}, common, {
        plugins: {
          title: { display: true, text: s.name + ': quality against cost' },
          tooltip: { callbacks: { label: function (c) {
            var p = c.raw;
            return p.label + ': ' + p.x.toPrecision(3) + ' ms, RMSE ' + p.y.toPrecision(3);
          } } }
        },
        scales: {
          x: { type: 'logarithmic', title: { display: true, text: 'ms per frame' } },
          y: { type: 'logarithmic', title: { display: true, text: 'RMSE' } }
        }
      })
    });
  });

  // Flicker: one pixel's value over the frames, the reference against every method.
  scenes.forEach(function (s) {
    var canvas = document.getElementById('chart-flicker-' + slug(s.name));
    if (!canvas || !s.flicker_pixel) return;
    var first = results.settings.frames[0];
    var frames = s.reference.trace.map(function (_, f) { return first + f; });
    var datasets = [{ label: 'reference', data: s.reference.trace, borderColor: '#000',
      backgroundColor: '#000', borderWidth: 3, pointRadius: 0 }];
    s.methods.forEach(function (m, k) {
      datasets.push({ label: m.label, data: m.trace, borderColor: colour(k),
        backgroundColor: colour(k), borderWidth: 1.5, pointRadius: 2 });
    });
    new Chart(canvas, {
      type: 'line',
      data: { labels: frames, datasets: datasets },
      options: Object.assign({}, common, {
        plugins: { title: { display: true, text: s.name + ': pixel (' + s.flicker_pixel.x + ', ' +
          s.flicker_pixel.y + ') over time' } },
        scales: {
          x: { title: { display: true, text: 'frame' } },
          y: { beginAtZero: true, title: { display: true, text: 'linear value' } }
        }
      })
    });
  });

  // Sliders: the method's picture over the reference's, cut at the slider's position.
  Array.prototype.forEach.call(document.querySelectorAll('.slider'), function (box) {
    var over = box.querySelector('img.over');
    var range = box.querySelector('input[type=range]');
    var select = box.querySelector('select');
    function cut() { over.style.clipPath = 'inset(0 ' + (100 - range.value) + '% 0 0)'; }
    range.addEventListener('input', cut);
    select.addEventListener('change', function () { over.src = select.value; });
    cut();
  });
})();
