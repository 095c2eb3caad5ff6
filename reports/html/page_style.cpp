#include "reports/html/page_style.h"

namespace cyclecert::html {

const std::string_view kPageStyle = R"css(
:root{--fg:#1d2330;--muted:#6b7280;--line:#d9dde3;--bg:#f4f5f7;--card:#fff;--head:#eef1f5;
--pass-bg:#d3efda;--pass-fg:#155d2b;--fail-bg:#f8d0d0;--fail-fg:#a01616;--ef-bg:#ffdcb0;--ef-fg:#8f4300;
--xf-bg:#dbe4f3;--xf-fg:#2c4a7c;--na-bg:#e4e6ea;--na-fg:#505866;--ut-fg:#858b95;--witness:#b0126f}
*{box-sizing:border-box}
html{font:14px/1.45 system-ui,-apple-system,"Segoe UI","DejaVu Sans","Liberation Sans",sans-serif;color:var(--fg);background:var(--bg)}
body{margin:0}
nav.top{position:sticky;top:0;z-index:10;display:flex;gap:1.4em;align-items:center;padding:.55em 1.5em;background:#1d2330;color:#fff}
nav.top a{color:#c9d3e3;text-decoration:none}nav.top a:hover{color:#fff}
nav.top .brand{font-weight:700;color:#fff;margin-right:.6em}
main{max-width:1320px;margin:0 auto;padding:1em 1.5em 3em}
[id]{scroll-margin-top:3.2em}
h1{font-size:1.65em;margin:.3em 0 .4em}
h2{font-size:1.25em;margin:1.8em 0 .6em;padding-bottom:.25em;border-bottom:2px solid var(--line)}
h3{font-size:1.1em;margin:1.5em 0 .5em}
h4{font-size:.78em;text-transform:uppercase;letter-spacing:.05em;color:var(--muted);margin:1em 0 .3em}
a{color:#1f4e8c}
code,pre{font-family:"DejaVu Sans Mono","Liberation Mono",ui-monospace,monospace;font-size:.9em}
.muted{color:var(--muted)}
.format-warning{background:var(--ef-bg);color:var(--ef-fg);padding:.5em .8em;border-radius:6px}
.headline{font-size:1.08em;font-weight:600;margin:.4em 0;padding:.55em .9em;border-radius:6px;border-left:6px solid}
.headline.v-pass{background:var(--pass-bg);color:var(--pass-fg)}
.headline.v-fail{background:var(--fail-bg);color:var(--fail-fg)}
.cards{display:grid;grid-template-columns:repeat(auto-fit,minmax(300px,1fr));gap:1em;margin:1em 0}
.card{background:var(--card);border:1px solid var(--line);border-radius:8px;padding:.8em 1em}
.card h2,.nonconforming h2{font-size:.78em;text-transform:uppercase;letter-spacing:.06em;color:var(--muted);border:0;margin:0 0 .5em;padding:0}
.nonconforming h2{margin-top:1.4em}
dl.facts{display:grid;grid-template-columns:max-content minmax(0,1fr);gap:.3em 1em;margin:0}
dl.facts dt{color:var(--muted)}dl.facts dd{margin:0}
.hash{font-size:.85em;word-break:break-all}
.big-number{margin:.1em 0 .6em}.big-number b{font-size:1.6em;margin-right:.2em}
table{border-collapse:collapse}
table.plain{width:100%}
table.plain th,table.plain td{text-align:left;padding:.3em .6em;border-bottom:1px solid #e7e9ed;vertical-align:top}
table.plain th{font-size:.85em;color:var(--muted);font-weight:600}
dl.nonconforming-list{display:grid;grid-template-columns:max-content minmax(0,1fr);gap:.4em 1em;margin:0;
 background:var(--card);border:1px solid var(--line);border-radius:8px;padding:.7em 1em}
dl.nonconforming-list dt{padding-top:.15em}dl.nonconforming-list dd{margin:0;line-height:1.9}
a.rule-chip,span.rule-chip{display:inline-block;background:var(--fail-bg);color:var(--fail-fg);border-radius:4px;padding:0 .45em;
 text-decoration:none;line-height:1.6;margin-right:.15em}
a.rule-chip:hover{text-decoration:underline}
.pills{display:flex;flex-wrap:wrap;gap:.4em;margin:0}
.pill,.badge{display:inline-block;padding:.12em .65em;border-radius:999px;white-space:nowrap;font-size:.92em}
.pill.zero{opacity:.45}
.pill.v-pass,.badge.v-pass,.cell.v-pass{background:var(--pass-bg);color:var(--pass-fg)}
.pill.v-fail,.badge.v-fail,.cell.v-fail{background:var(--fail-bg);color:var(--fail-fg)}
.pill.v-engine-failure,.badge.v-engine-failure,.cell.v-engine-failure{background:var(--ef-bg);color:var(--ef-fg)}
.pill.v-not-applicable,.badge.v-not-applicable,.cell.v-not-applicable{background:var(--na-bg);color:var(--na-fg)}
.pill.v-untested,.badge.v-untested,.cell.v-untested,.cell.v-unknown{color:var(--ut-fg);
 background:repeating-linear-gradient(135deg,#fff 0 5px,#eceef1 5px 10px)}
.sym.v-pass{color:var(--pass-fg)}.sym.v-fail{color:var(--fail-fg)}.sym.v-engine-failure{color:var(--ef-fg)}
.sym.v-not-applicable{color:var(--na-fg)}.sym.v-untested{color:var(--ut-fg)}
.table-wrap{overflow-x:auto}
table.engine-summary{background:var(--card);border:1px solid var(--line);width:100%;font-size:.95em}
table.engine-summary th,table.engine-summary td{padding:.3em .6em;border-bottom:1px solid #e7e9ed;text-align:left;white-space:nowrap}
table.engine-summary thead th{font-size:.85em;color:var(--muted);font-weight:600;background:var(--head)}
table.engine-summary thead tr:first-child th{color:var(--fg);font-size:.8em;text-transform:uppercase;letter-spacing:.05em}
table.engine-summary .group-start{border-left:2px solid var(--line)}
table.engine-summary th.engine{font-size:1.05em;white-space:normal;min-width:12em}
table.engine-summary .version{font-weight:normal;font-size:.8em;color:var(--muted);overflow-wrap:anywhere}
td.num,th.num{text-align:right!important;font-variant-numeric:tabular-nums}
td.num.zero{color:#b5bac2}
td.num.v-fail:not(.zero){color:var(--fail-fg);font-weight:700}
td.num.v-engine-failure:not(.zero){color:var(--ef-fg);font-weight:700}
td.num.v-pass:not(.zero){color:var(--pass-fg)}
td.num.total{font-weight:700}
td.seeds{white-space:normal!important;max-width:16em}
td.seeds code{font-size:.8em}
.legend{display:flex;flex-wrap:wrap;gap:.5em;align-items:center;margin:.4em 0}
.legend .key{padding:.15em .7em;border-radius:4px;border:1px solid #e1e4e8}
.legend-note{color:var(--muted);font-size:.9em;margin-left:.4em}
.toolbar{display:none}
.js .toolbar{display:flex;gap:1.2em;align-items:center;margin:.6em 0}
.toolbar input[type=search]{padding:.3em .6em;border:1px solid var(--line);border-radius:5px;min-width:18em;font:inherit}
.matrix-wrap{overflow-x:auto;background:var(--card);border:1px solid var(--line);border-radius:8px}
table.matrix{width:100%;font-size:.92em}
table.matrix th,table.matrix td{padding:.24em .6em;border-bottom:1px solid #eceef1;text-align:left}
table.matrix thead th{border-bottom:2px solid var(--line);padding:.5em .6em;background:var(--card)}
table.matrix thead th.engine{text-align:left}
tr.cycle th{background:var(--head);padding:.4em .6em;font-size:1em}
th.rule-id{font-weight:normal;white-space:nowrap}
td.summary{max-width:0;width:100%;white-space:nowrap;overflow:hidden;text-overflow:ellipsis;color:#3d4451}
td.cell{white-space:nowrap;min-width:11.5em;border-left:3px solid var(--card)}
.cell .sym{font-weight:700}
.cell .n{font-size:.82em;opacity:.85;margin-left:.15em}
.cell .links a,.cell .more{color:inherit;font-weight:700;font-size:.82em;margin-left:.3em}
tr.rule:hover td,tr.rule:hover th{filter:brightness(.96)}
tr.rule:target th,tr.rule:target td.summary{background:#fff6c9}
.section-note{color:var(--muted);max-width:70em}
.note{background:#fff8e1;border:1px solid #f1dca0;padding:.45em .8em;border-radius:6px}
article.failure{background:var(--card);border:1px solid var(--line);border-left:5px solid var(--fail-fg);border-radius:8px;margin:1em 0;padding:.8em 1em}
article.failure.v-engine-failure{border-left-color:var(--ef-fg)}
article.failure.v-expected{border-left-color:var(--xf-fg)}
.pill.v-expected,.badge.v-expected{background:var(--xf-bg);color:var(--xf-fg)}
h4.expected-failures{color:var(--xf-fg)}
article.failure:target{box-shadow:0 0 0 3px #f3d36b}
article.failure header{display:flex;align-items:center;gap:.6em;flex-wrap:wrap}
.fid{font-weight:700;color:var(--fg);text-decoration:none;font-size:1.05em}
.case-id{font-weight:600;font-size:1em;overflow-wrap:anywhere}
.kind{font-size:.75em;text-transform:uppercase;letter-spacing:.06em;background:var(--head);color:var(--muted);padding:.1em .5em;border-radius:4px}
.failure-body{display:grid;grid-template-columns:minmax(0,1fr) minmax(0,1.25fr);gap:1.4em;margin-top:.6em}
@media (max-width:1000px){.failure-body{grid-template-columns:minmax(0,1fr)}}
dl.case-facts{display:grid;grid-template-columns:max-content minmax(0,1fr);gap:.25em 1em;margin:0}
dl.case-facts dt{color:var(--muted)}dl.case-facts dd{margin:0;overflow-wrap:anywhere}
dl.case-facts a{margin-right:.3em}
.detail{background:#fafbfc;border-left:3px solid var(--line);padding:.4em .7em;margin:.6em 0;white-space:pre-wrap;overflow-wrap:anywhere}
ul.findings{padding-left:1.1em;margin:.4em 0}ul.findings li{margin:.25em 0;overflow-wrap:anywhere}
.oracle{font-weight:600;color:var(--witness);background:#fbe4f1;padding:0 .35em;border-radius:3px}
.move{font-weight:600}
.finding-rules code{font-size:.8em}
pre.program,pre.reproduce{background:#1d2330;color:#e6eaf0;padding:.6em .8em;border-radius:6px;margin:.2em 0;overflow-x:auto}
pre.reproduce{white-space:pre-wrap;word-break:break-all}
figure.plot{margin:0}
svg.plot-svg{display:block;width:100%;height:auto;border:1px solid var(--line);border-radius:6px;background:#fff}
.no-plot,.plot-error{padding:2em 1em;text-align:center;border:1px dashed var(--line);border-radius:6px;color:var(--muted)}
.plot-error{color:var(--fail-fg);background:#fff5f5;border-color:var(--fail-bg)}
footer{margin-top:3em;color:var(--muted);font-size:.85em}
@media print{nav.top,.toolbar{display:none!important}article.failure{break-inside:avoid}html{background:#fff}}
)css";

const std::string_view kPageScript = R"js(
(function () {
  'use strict';
  document.documentElement.classList.add('js');
  var table = document.getElementById('matrix');
  var onlyBad = document.getElementById('matrix-only-nonconforming');
  var filter = document.getElementById('matrix-filter');
  var shown = document.getElementById('matrix-shown');
  if (!table || !onlyBad || !filter || !shown) return;
  function apply() {
    var needle = filter.value.trim().toLowerCase();
    var total = 0, visible = 0;
    for (var g = 0; g < table.tBodies.length; g++) {
      var rows = table.tBodies[g].querySelectorAll('tr.rule');
      var inGroup = 0;
      for (var i = 0; i < rows.length; i++) {
        var row = rows[i];
        var keep = (!onlyBad.checked || row.getAttribute('data-nonconforming') === '1') &&
                   (needle === '' || row.textContent.toLowerCase().indexOf(needle) >= 0);
        row.hidden = !keep;
        total++;
        if (keep) { inGroup++; visible++; }
      }
      table.tBodies[g].hidden = rows.length > 0 && inGroup === 0;
    }
    shown.textContent = visible === total ? total + ' rules' : visible + ' of ' + total + ' rules';
  }
  onlyBad.addEventListener('change', apply);
  filter.addEventListener('input', apply);
  apply();
})();
)js";

}  // namespace cyclecert::html
