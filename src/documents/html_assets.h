#pragma once
// The style sheet and the script every HTML report embeds (html.cpp): table sorting and filtering,
// the gallery's search.

namespace fl::documents {

inline constexpr const char* kHtmlStyle = R"CSS(
body{font:14px/1.45 "DejaVu Sans",system-ui,sans-serif;margin:0;color:#1e1e1e;background:#f7f7f7;overflow-wrap:anywhere}
header{background:#1e1e1e;color:#eee;padding:14px 20px}header h1{margin:0 0 6px;font-size:22px}
header p{margin:4px 0;color:#ccc}header a{color:#9cf}header code{background:#333;color:#eee}nav{margin-top:8px}nav a{margin-right:14px;display:inline-block;overflow-wrap:normal}
main{max-width:1280px;margin:0 auto;padding:8px 20px 40px}@media(max-width:600px){main,header{padding-left:10px;padding-right:10px}}h2{margin:24px 0 8px}
input[type=search]{font:inherit;padding:4px 8px;width:320px;max-width:90%;border:1px solid #bbb;border-radius:4px}
.count{color:#666;margin-left:10px}
.gallery{display:grid;grid-template-columns:repeat(auto-fill,minmax(min(290px,100%),1fr));gap:12px;margin-top:12px}
.card{background:#fff;border:1px solid #ddd;border-radius:6px;padding:10px 12px;min-width:0}.card[hidden]{display:none}
.card h3{margin:0;font-size:16px}.cls{color:#777;font-weight:normal;font-size:13px;margin-left:6px;display:inline-block;white-space:nowrap;overflow-wrap:normal}
#groups{display:flex;flex-direction:column}.group{margin-top:18px}.group[hidden]{display:none}.group>h3{margin:0;font-size:17px;border-bottom:1px solid #ddd;padding-bottom:2px}.gallery[data-src]{min-height:120px}
.src{color:#666;font-size:12px;word-break:break-all}
.strip{height:20px;border-radius:3px;margin:8px 0 2px;border:1px solid #555;box-shadow:0 0 0 3px #808080}.strip-axis{display:flex;justify-content:space-between;font-size:11px;color:#888}
.sws{margin:8px 0 6px;padding:5px 8px;display:inline-block;border-radius:4px;background:repeating-conic-gradient(#6e6e6e 0 25%,#8c8c8c 0 50%) 0 0/10px 10px}
.sw{display:inline-block;width:26px;height:26px;border:1px solid #222;border-radius:3px;vertical-align:middle;margin-right:4px}
.swl{margin-right:14px;font-size:12px;color:#fff;text-shadow:0 0 2px #000}
.flag{display:inline-block;background:#fde6c8;color:#7a3d00;border-radius:10px;padding:0 8px;font-size:12px;margin:2px 4px 2px 0}
.facts{display:grid;grid-template-columns:auto 1fr;gap:0 10px;font-size:12px;margin:6px 0}.facts dt{color:#666}.facts dd{margin:0;min-width:0}
.flip{margin:8px 0;max-width:100%;overflow-x:auto}.flip-img{cursor:pointer;background-repeat:no-repeat;border-radius:4px;background-color:#111}
.flip-label{font-size:12px;color:#444;margin:2px 0}.flip button{font:inherit;font-size:12px;margin:0 4px 4px 0;padding:1px 8px;border:1px solid #bbb;background:#f3f3f3;border-radius:10px;cursor:pointer}
.flip button[aria-pressed=true]{background:#1e1e1e;color:#fff}
details.tbl{background:#fff;border:1px solid #ddd;border-radius:6px;margin:8px 0;padding:4px 12px}
details.tbl>summary{cursor:pointer;padding:4px 0;font-weight:bold}.sum{font-weight:normal;color:#666}
.tablewrap{overflow:auto;max-height:70vh;margin:8px 0;border:1px solid #ddd}
table{border-collapse:collapse;font-size:12px}th,td{border:1px solid #e2e2e2;padding:2px 6px;text-align:right;white-space:nowrap}
td.t,th.t{text-align:left}th{cursor:pointer;position:sticky;top:0;background:#eee;user-select:none}
th[aria-sort=ascending]::after{content:" \25B2"}th[aria-sort=descending]::after{content:" \25BC"}
tr[hidden]{display:none}code{background:#eee;padding:0 3px;border-radius:3px}img.fig{max-width:100%;margin-top:6px}
.figcap{font-size:12px;margin:0 0 6px}
#summary ul{background:#fff;border:1px solid #ddd;border-radius:6px;padding:8px 12px 8px 30px;margin:0}#summary li{margin:3px 0}
figure{margin:12px 0}figure img{max-width:100%;height:auto}.sheets{display:grid;grid-template-columns:repeat(auto-fill,minmax(min(380px,100%),1fr));gap:12px}
.sheets figure{margin:0;background:#fff;border:1px solid #ddd;border-radius:6px;padding:8px}
)CSS";

// The page's behaviour: sortable tables, row and gallery filters, flips.
inline constexpr const char* kHtmlScript = R"JS(
(function () {
  'use strict';
  function value(td) {
    var v = td.getAttribute('data-v');
    if (v === null) return td.textContent;
    return v === '' ? NaN : parseFloat(v);
  }
  var collator = new Intl.Collator(undefined, { numeric: true });
  function compare(x, y, sign) {
    if (typeof x === 'number' && typeof y === 'number') {
      if (isNaN(x) || isNaN(y)) return isNaN(x) ? (isNaN(y) ? 0 : 1) : -1;
      return sign * (x - y);
    }
    return sign * collator.compare(String(x), String(y));
  }
  function sortBy(th) {
    var table = th.closest('table'), index = Array.prototype.indexOf.call(th.parentNode.children, th);
    var dir = th.getAttribute('aria-sort') === 'ascending' ? 'descending' : 'ascending';
    table.querySelectorAll('th').forEach(function (h) { h.removeAttribute('aria-sort'); });
    th.setAttribute('aria-sort', dir);
    var body = table.tBodies[0], sign = dir === 'ascending' ? 1 : -1;
    var keyed = Array.prototype.map.call(body.rows, function (r) { return [value(r.cells[index]), r]; });
    keyed.sort(function (a, b) { return compare(a[0], b[0], sign); });
    var rows = document.createDocumentFragment();
    keyed.forEach(function (k) { rows.appendChild(k[1]); });
    body.appendChild(rows);
  }
  function matches(text, query) {
    var terms = query.toLowerCase().split(/\s+/).filter(Boolean);
    text = text.toLowerCase();
    return terms.every(function (t) { return text.indexOf(t) >= 0; });
  }
  function filterRows(input) {
    var table = document.getElementById(input.getAttribute('data-table')), shown = 0;
    Array.prototype.forEach.call(table.tBodies[0].rows, function (r) {
      r.hidden = !matches(r.textContent, input.value);
      if (!r.hidden) shown++;
    });
    input.nextElementSibling.textContent = shown + ' of ' + table.tBodies[0].rows.length + ' rows';
  }
  function filterGallery(input) {
    var cards = document.querySelectorAll('.card'), shown = 0;
    cards.forEach(function (c) {
      c.hidden = !matches(c.getAttribute('data-search'), input.value);
      if (!c.hidden) shown++;
    });
    document.getElementById('gallery-count').textContent = shown + ' of ' + cards.length + ' materials';
  }
  function setupFlip(flip) {
    var img = flip.querySelector('.flip-img'), label = flip.querySelector('.flip-label');
    var size = parseInt(flip.getAttribute('data-size'), 10), labels = JSON.parse(flip.getAttribute('data-labels'));
    var buttons = flip.querySelectorAll('button');
    function show(i) {
      flip.setAttribute('data-frame', String(i));
      img.style.backgroundPosition = (-i * size) + 'px 0';
      label.textContent = labels[i];
    }
    function select(i) {
      flip.setAttribute('data-model', String(i));
      buttons.forEach(function (b) { b.setAttribute('aria-pressed', String(b.getAttribute('data-frame') === String(i))); });
    }
    buttons.forEach(function (b) {
      var i = parseInt(b.getAttribute('data-frame'), 10);
      b.addEventListener('mouseenter', function () { show(i); });
      b.addEventListener('mouseleave', function () { show(0); });
      b.addEventListener('click', function () { select(i); show(i); });
    });
    img.addEventListener('click', function () {
      show(flip.getAttribute('data-frame') === '0' ? parseInt(flip.getAttribute('data-model'), 10) : 0);
    });
    select(parseInt(flip.getAttribute('data-model'), 10));
  }
  function setupTables(root) {
    root.querySelectorAll('th').forEach(function (th) { th.addEventListener('click', function () { sortBy(th); }); });
    root.querySelectorAll('input[data-table]').forEach(function (i) {
      i.addEventListener('input', function () { filterRows(i); });
    });
  }
  setupTables(document);
  // A table kept in a script beside the page is loaded when its section is first opened.
  window.flTable = function (id, html) {
    var box = document.getElementById(id);
    box.innerHTML = html;
    box.removeAttribute('data-src');
    setupTables(box);
  };
  document.querySelectorAll('details.tbl').forEach(function (d) {
    d.addEventListener('toggle', function () {
      var box = d.querySelector('[data-src]');
      if (!d.open || !box || box.hasAttribute('data-loading')) return;
      box.setAttribute('data-loading', '');
      var s = document.createElement('script');
      s.src = box.getAttribute('data-src');
      document.body.appendChild(s);
    });
  });
  var g = document.getElementById('gallery-filter');
  if (g && !document.getElementById('gallery-index')) g.addEventListener('input', function () { filterGallery(g); });
  document.querySelectorAll('.flip').forEach(setupFlip);
})();
)JS";

}  // namespace fl::documents
