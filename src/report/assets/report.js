// The report page's script (sunglint compare): draws the charts with Chart.js from the
// results embedded in the page, and drives the reference/method sliders. Plain ES2017,
// no modules, so the page works from file://.
(function () {
  'use strict';
  var results = JSON.parse(document.getElementById('sg-results').textContent);
  // A qualitative palette of 12 colours that stay apart on white and for the common colour
  // vision deficiencies (Okabe and Ito's 7, then Paul Tol's muted wine, olive, indigo, teal
  // and purple), and 4 dash patterns: method k gets colour k mod 12 and dash (k + floor(k /
  // 12)) mod 4, so no two of the first 48 methods look alike, and neighbours differ in both.
  // Bars cannot be dashed: from the 13th method on they are hatched.
  var palette = ['#0072B2', '#E69F00', '#009E73', '#D55E00', '#CC79A7', '#56B4E9', '#882255',
    '#999933', '#332288', '#44AA99', '#AA4499', '#000000'];
  var dashes = [[], [6, 3], [2, 2], [8, 3, 2, 3]];
  var methods = results.settings.methods;
  var scenes = results.scenes;

  function colour(k) { return palette[k % palette.length]; }
  function dash(k) { return dashes[(k + Math.floor(k / palette.length)) % dashes.length]; }
  function hatched(k) {
    var c = document.createElement('canvas');
    c.width = c.height = 8;
    var g = c.getContext('2d');
    g.fillStyle = '#ffffff';
    g.fillRect(0, 0, 8, 8);
    g.strokeStyle = colour(k);
    g.lineWidth = 3;
    g.beginPath();
    g.moveTo(0, 8); g.lineTo(8, 0); g.moveTo(-2, 2); g.lineTo(2, -2); g.moveTo(6, 10); g.lineTo(10, 6);
    g.stroke();
    return g.createPattern(c, 'repeat');
  }
  function barFill(k) { return k < palette.length ? colour(k) : hatched(k); }
  // The ticks of a logarithmic axis, never rotated and never closer than a label's size:
  // 1, 2 and 5 times the powers of ten where a decade is long enough on screen, else 1 and 3,
  // else the powers of ten, else every second, fifth, ... of them (Chart.js's own log ticks
  // label 1 to 9 of each decade and its ends, which run into each other).
  var mantissaSets = [[1, 2, 5], [1, 3], [1]];
  var mantissaGaps = [Math.log10(2), Math.log10(3), 1];
  function logTickValues(axis) {
    var lo = axis.min, hi = axis.max;
    if (!(lo > 0) || !(hi > lo)) return;
    var horizontal = axis.isHorizontal();
    var length = horizontal ? axis.width : axis.height;
    var perDecade = length / Math.max(Math.log10(hi / lo), 1e-9);
    // Room a label needs along the axis: a number's width across, a line's height upwards.
    var need = horizontal ? 44 : 18;
    var set = [1], step = 1;
    for (var k = 0; k < mantissaSets.length; ++k) {
      if (perDecade * mantissaGaps[k] >= need) { set = mantissaSets[k]; break; }
    }
    if (set.length === 1 && perDecade < need) step = Math.ceil(need / Math.max(perDecade, 1e-9));
    var ticks = [];
    for (var e = Math.floor(Math.log10(lo)) - 1; e <= Math.ceil(Math.log10(hi)); ++e) {
      if (((e % step) + step) % step !== 0) continue;
      set.forEach(function (m) {
        var v = Number((m * Math.pow(10, e)).toPrecision(1));
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) ticks.push({ value: v });
      });
    }
    if (ticks.length > 0) axis.ticks = ticks;
  }
  function logAxis(title) {
    return {
      type: 'logarithmic', title: { display: true, text: title }, afterBuildTicks: logTickValues,
      ticks: { autoSkip: false, maxRotation: 0, minRotation: 0,
        callback: function (value) { return Number(value.toPrecision(1)).toString(); } }
    };
  }
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
  // Markers of the scatter and line charts, by method (the equal-cost target is a star).
  var pointStyles = ['rectRot', 'circle', 'triangle', 'rect', 'crossRot', 'rectRounded'];

  // A value a logarithmic axis can show (null for a missing or non-positive one).
  function positive(x) { return typeof x === 'number' && x > 0 ? x : null; }

  // One bar per method and scene, on a logarithmic axis: the scenes' values span orders of
  // magnitude (a colour scene's radiances are hundreds of times a grey one's).
  function bars(id, title, value, yTitle) {
    var canvas = document.getElementById(id);
    if (!canvas) return;
    new Chart(canvas, {
      type: 'bar',
      data: {
        labels: scenes.map(function (s) { return s.name; }),
        datasets: methods.map(function (m, k) {
          return { label: m, backgroundColor: barFill(k), borderColor: colour(k), borderWidth: 1,
            data: scenes.map(function (s) { return positive(value(s, m)); }) };
        })
      },
      options: Object.assign({}, common, {
        plugins: { title: { display: true, text: title } },
        scales: { y: logAxis(yTitle), x: { ticks: { autoSkip: false } } }
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
  }, 'ms per frame');

  // Near and far halves of the water: one group per scene and half.
  (function () {
    var canvas = document.getElementById('chart-nearfar');
    if (!canvas) return;
    var labels = [], pairs = [];
    scenes.forEach(function (s) {
      // Two lines (the scene, then the half): narrow enough to stand upright.
      ['near', 'far'].forEach(function (r) { labels.push([s.name, r]); pairs.push([s, r]); });
    });
    new Chart(canvas, {
      type: 'bar',
      data: {
        labels: labels,
        datasets: methods.map(function (m, k) {
          return { label: m, backgroundColor: barFill(k), borderColor: colour(k), borderWidth: 1,
            data: pairs.map(function (p) { return positive(metric(p[0], m, p[1], 'rmse')); }) };
        })
      },
      options: Object.assign({}, common, {
        plugins: { title: { display: true, text: 'RMSE in the near and far halves of the water' } },
        scales: { y: logAxis('RMSE'), x: { ticks: { autoSkip: false, maxRotation: 0 } } }
      })
    });
  })();

  // Quality-cost: the supersampling budgets as a curve, each method as a point.
  scenes.forEach(function (s) {
    var canvas = document.getElementById('chart-cost-' + slug(s.name));
    if (!canvas) return;
    var positive = function (p) { return p.x > 0 && p.y > 0; };
    var datasets = [{
      label: 'supersample (budgets)', showLine: true, borderColor: '#777', backgroundColor: '#777',
      borderWidth: 2, borderDash: [4, 4], pointStyle: 'circle',
      data: s.budgets.map(function (b) {
        return { x: b.ms_per_frame, y: b.regions.image.rmse, spp: b.spp, label: b.label };
      }).filter(positive)
    }];
    s.methods.forEach(function (m) {
      var k = methods.indexOf(m.label);
      var target = results.settings.equal_cost_target === m.label;
      datasets.push({ label: m.label, backgroundColor: colour(k), borderColor: colour(k),
        pointRadius: target ? 9 : 6, pointStyle: target ? 'star' : pointStyles[k % pointStyles.length],
        borderWidth: target ? 2 : 1,
        data: [{ x: m.ms_per_frame, y: m.regions.image.rmse, label: m.label }].filter(positive) });
    });
    new Chart(canvas, {
      type: 'scatter',
      data: { datasets: datasets },
      options: Object.assign({}, common, {
        plugins: {
          title: { display: true, text: s.name + ': quality against cost' },
          legend: { labels: { usePointStyle: true } },
          tooltip: { callbacks: { label: function (c) {
            var p = c.raw;
            return p.label + ': ' + p.x.toPrecision(3) + ' ms, RMSE ' + p.y.toPrecision(3);
          } } }
        },
        scales: { x: logAxis('ms per frame'), y: logAxis('RMSE') }
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
    s.methods.forEach(function (m) {
      var k = methods.indexOf(m.label);
      datasets.push({ label: m.label, data: m.trace, borderColor: colour(k),
        backgroundColor: colour(k), borderWidth: 1.5, borderDash: dash(k), pointRadius: 2,
        pointStyle: pointStyles[k % pointStyles.length] });
    });
    new Chart(canvas, {
      type: 'line',
      data: { labels: frames, datasets: datasets },
      options: Object.assign({}, common, {
        plugins: { title: { display: true, text: s.name + ': pixel (' + s.flicker_pixel.x + ', ' +
          s.flicker_pixel.y + ') over time' }, legend: { labels: { usePointStyle: true } } },
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
