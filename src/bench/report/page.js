// bench's report.html: draws its plots with Chart.js from the page's data
// (the JSON in #report-data, written by src/bench/ReportPlots.cpp), removes
// the plots the runs have no data for, and writes into the DOM what a test
// reads: how many images decoded (data-images-loaded), each plot's points
// and labels (data-points, data-labels, data-series), and where the
// table's accuracy columns and the plots lie (data-layout).
'use strict';
(() => {
  const data = JSON.parse(document.getElementById('report-data').textContent);
  Chart.defaults.animation = false;  // drawn at once: the layout and a screenshot see the final plot
  Chart.defaults.font.family = 'system-ui, sans-serif';
  Chart.defaults.color = '#222';
  const FRONT = '#dd6b20', OTHER = '#2b6cb0';

  // Each point's row number beside it, at the first of four places (right
  // above, left above, right below, left below) that overlaps no point and
  // no label placed before; none when all four do (the tooltip names it).
  const rowLabels = {
    id: 'rowLabels',
    afterDatasetsDraw(chart) {
      const ctx = chart.ctx, placed = [], points = [];
      chart.data.datasets.forEach((set, d) => chart.getDatasetMeta(d).data.forEach((el, i) => {
        points.push({x: el.x, y: el.y, text: String(set.data[i].row), row: set.data[i].row});
        placed.push([el.x - 5, el.y - 5, el.x + 5, el.y + 5]);
      }));
      points.sort((a, b) => a.row - b.row);
      ctx.save();
      ctx.font = '10px system-ui, sans-serif';
      ctx.fillStyle = '#222';
      let labels = 0;
      for (const p of points) {
        const w = ctx.measureText(p.text).width;
        for (const [dx, dy] of [[7, -6], [-7 - w, -6], [7, 14], [-7 - w, 14]]) {
          const box = [p.x + dx, p.y + dy - 10, p.x + dx + w, p.y + dy];
          if (placed.some(o => box[0] < o[2] && o[0] < box[2] && box[1] < o[3] && o[1] < box[3])) continue;
          placed.push(box);
          ctx.fillText(p.text, p.x + dx, p.y + dy);
          ++labels;
          break;
        }
      }
      ctx.restore();
      chart.canvas.dataset.labels = labels;
    },
  };

  const axis = (title, extra) => Object.assign({title: {display: true, text: title}, beginAtZero: true, grid: {color: '#e4e4e4'}}, extra || {});

  function scatter(plot) {
    const canvas = document.getElementById(plot.id);
    const dataset = (label, colour, front) => ({
      label, data: plot.points.filter(p => p.front === front), pointRadius: 5, pointHoverRadius: 7,
      backgroundColor: colour + 'bf', borderColor: colour,
    });
    new Chart(canvas, {
      type: 'scatter',
      data: {datasets: [dataset("on its scene's front", FRONT, true), dataset('the other rows', OTHER, false)]},
      options: {
        responsive: false,
        scales: {x: axis('frame time, median (ms)'), y: axis(plot.axis)},
        plugins: {tooltip: {callbacks: {label: c => c.raw.name}}, legend: {position: 'bottom'}},
      },
      plugins: [rowLabels],
    });
    canvas.dataset.points = plot.points.length;
  }

  function lightCount(series) {
    const canvas = document.getElementById('lightcount');
    const counts = series.flatMap(s => s.points.map(p => Math.max(p[0], 1)));
    const least = Math.floor(Math.log2(Math.min(...counts))), most = Math.max(Math.ceil(Math.log2(Math.max(...counts))), least + 1);
    new Chart(canvas, {
      type: 'line',
      data: {datasets: series.map(s => ({
        label: s.label, borderColor: s.colour, backgroundColor: s.colour, borderWidth: 2, pointRadius: 3.5,
        data: s.points.map(([n, ms]) => ({x: Math.log2(Math.max(n, 1)), y: ms, n})),
      }))},
      options: {
        responsive: false,
        scales: {
          x: axis('lights (lightGrid.count)', {type: 'linear', min: least, max: most, offset: true, ticks: {stepSize: 1, callback: v => 2 ** v}}),
          y: axis('frame time, median (ms)'),
        },
        plugins: {tooltip: {callbacks: {label: c => `${c.dataset.label}: ${c.raw.n} lights, ${c.raw.y.toFixed(1)} ms`}}, legend: {position: 'bottom'}},
      },
    });
    canvas.dataset.series = series.length;
  }

  for (const id of ['scatter', 'scatter-soft']) {
    const plot = data.plots.find(p => p.id === id);
    if (plot) scatter(plot);
    else document.getElementById(id).parentElement.remove();
  }
  if (!data.plots.length) document.getElementById('plots').remove();
  if (data.lightCount.length) lightCount(data.lightCount);
  else document.getElementById('lightcount-section').remove();

  window.addEventListener('load', () => {
    const images = Array.from(document.images);
    const ok = images.filter(i => i.complete && i.naturalWidth > 0).length;
    document.body.dataset.imagesLoaded = ok + '/' + images.length;
    // CSS pixels from the page's top left, for a test in a browser of a given size.
    const rect = e => { const r = e.getBoundingClientRect(); return {x: r.left + scrollX, y: r.top + scrollY, width: r.width, height: r.height}; };
    const heads = Array.from(document.querySelectorAll('#results th'));
    const accuracy = heads.filter(th => /misclassified|false lit|false shadow|RMSE/.test(th.textContent)).map(rect);
    const plots = Array.from(document.querySelectorAll('.plot canvas')).map(e => Object.assign({id: e.id}, rect(e)));
    const rows = document.querySelectorAll('#results > tbody > tr').length;  // with the heading row
    document.body.dataset.layout = JSON.stringify({viewport: {width: innerWidth, height: innerHeight}, accuracy, plots, rows});
  });
})();
