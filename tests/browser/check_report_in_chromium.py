#!/usr/bin/env python3
"""Open cyclecert's index.html in headless Chromium and check that it really renders.

    check_report_in_chromium.py INDEX_HTML
    check_report_in_chromium.py --render-with RENDER_REPORT REPORT_JSON   (tests/browser/render_report.cpp)
    check_report_in_chromium.py --self-test
    check_report_in_chromium.py INDEX_HTML --screenshot PNG [--window-size 1400,1800]

Checks, on the page as Chromium leaves it (`--dump-dom`):
  - no script error: nothing uncaught (thrown, syntax, in a timer, a rejected promise), no
    console.error/console.warn, no resource that failed to load — seen both by a hook this script
    puts first in a copy of the page's <head> and in Chromium's own console log on stderr;
  - the page refers to nothing outside itself (no element with src, no <link>, no style sheet with
    an address, no url() in its style, nothing in the Resource Timing list);
  - the page's own script ran (it marks <html> with class "js");
  - the traceability matrix (table#matrix with rule rows) and at least one plot (svg.plot-svg with
    a path) are in the DOM.
`--self-test` proves each check can fail: it renders small pages that throw, log an error, load a
file, lack the matrix or the plot, and expects each to be caught (and a clean page to pass).

Python 3 standard library only; Chromium is Debian's `chromium` package (/usr/bin/chromium, or
--chromium PATH). Exit: 0 all checks pass, 1 a check failed (each failure on its own line),
2 bad usage or a page/report that cannot be read, 77 Chromium is not installed (CTest's
SKIP_RETURN_CODE).
"""
import argparse
import html.parser
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

SKIP = 77
DEFAULT_CHROMIUM = "/usr/bin/chromium"
CHROMIUM_TIMEOUT_S = 120

# Runs before any of the page's own scripts: records every error the page raises on <html>'s
# attributes, which --dump-dom then carries out of the browser.
HOOK = """<script data-cc-hook>/* injected by check_report_in_chromium.py */
(function () {
  var root = document.documentElement, errors = [];
  function note(message) { errors.push(String(message)); root.setAttribute('data-cc-errors', JSON.stringify(errors)); }
  root.setAttribute('data-cc-errors', '[]');
  window.addEventListener('error', function (e) {
    var t = e.target;
    if (t && t !== window && (t.src || t.href)) note('resource failed to load: ' + (t.src || t.href));
    else note('uncaught: ' + e.message + ' (line ' + e.lineno + ')');
  }, true);
  window.addEventListener('unhandledrejection', function (e) { note('unhandled promise rejection: ' + e.reason); });
  ['error', 'warn'].forEach(function (level) {
    var original = console[level];
    console[level] = function () {
      note('console.' + level + ': ' + Array.prototype.join.call(arguments, ' '));
      return original.apply(console, arguments);
    };
  });
  window.addEventListener('load', function () {
    // What the page fetched (Resource Timing lists http(s) fetches only, hence the DOM too).
    var loaded = performance.getEntriesByType('resource').map(function (r) { return r.name; });
    Array.prototype.forEach.call(document.querySelectorAll('[src], link[href], object[data]'), function (el) {
      if (el.hasAttribute('data-cc-hook')) return;
      loaded.push(el.tagName.toLowerCase() + ' ' + (el.getAttribute('src') || el.getAttribute('href') || el.getAttribute('data')));
    });
    Array.prototype.forEach.call(document.styleSheets, function (sheet) {
      if (sheet.href) loaded.push('style sheet ' + sheet.href);
      try {
        Array.prototype.forEach.call(sheet.cssRules, function (rule) {
          if (rule.href) loaded.push('@import ' + rule.href);
          if (rule.cssText && /url\(/.test(rule.cssText)) loaded.push('css ' + rule.cssText.slice(0, 80));
        });
      } catch (e) { loaded.push('unreadable style sheet ' + sheet.href); }
    });
    root.setAttribute('data-cc-resources', JSON.stringify(loaded));
    root.setAttribute('data-cc-loaded', '1');
  });
})();
</script>
"""

# Chromium's console log lines that mean an error (it logs every console message at INFO level,
# so the message text decides).
CONSOLE_ERROR = re.compile(r':CONSOLE[^\]]*\] "(Uncaught[^"]*|Failed to load resource[^"]*|Refused to[^"]*)"')


class UsageError(Exception):
    pass


class DomSummary(html.parser.HTMLParser):
    """What the checks need from the dumped DOM."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.root_attrs = {}
        self.matrix_tables = 0
        self.matrix_rule_rows = 0
        self.plots = 0
        self.plot_paths = 0
        self._in_matrix = 0  # depth of <table> inside table#matrix
        self._in_plot = 0    # depth of <svg> inside svg.plot-svg

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        classes = (a.get("class") or "").split()
        if tag == "html" and not self.root_attrs:
            self.root_attrs = a
        if tag == "table":
            if self._in_matrix:
                self._in_matrix += 1
            elif a.get("id") == "matrix":
                self.matrix_tables += 1
                self._in_matrix = 1
        if tag == "tr" and self._in_matrix and "rule" in classes:
            self.matrix_rule_rows += 1
        if tag == "svg":
            if self._in_plot:
                self._in_plot += 1
            elif "plot-svg" in classes:
                self.plots += 1
                self._in_plot = 1
        if tag == "path" and self._in_plot:
            self.plot_paths += 1

    def handle_startendtag(self, tag, attrs):
        self.handle_starttag(tag, attrs)
        self.handle_endtag(tag)

    def handle_endtag(self, tag):
        if tag == "table" and self._in_matrix:
            self._in_matrix -= 1
        if tag == "svg" and self._in_plot:
            self._in_plot -= 1


def inject_hook(page: str) -> str:
    head = re.search(r"<head(\s[^>]*)?>", page, re.IGNORECASE)
    if not head:
        raise UsageError("the page has no <head> element")
    return page[: head.end()] + "\n" + HOOK + page[head.end():]


def run_chromium(chromium, args, workdir):
    """Runs Chromium in its own process group (killed whole on timeout); returns (rc, out, err)."""
    cmd = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
           "--disable-background-networking", f"--user-data-dir={workdir / 'profile'}"] + args
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=CHROMIUM_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None, "", f"chromium did not finish within {CHROMIUM_TIMEOUT_S} s"
    return proc.returncode, out.decode("utf-8", "replace"), err.decode("utf-8", "replace")


def check_page(chromium, page_path: Path):
    """Every check on one page; returns the list of failures (empty when it passes)."""
    try:
        page = page_path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise UsageError(f"cannot read {page_path}: {e}")
    with tempfile.TemporaryDirectory(prefix="cyclecert-chromium-") as tmp:
        workdir = Path(tmp)
        # Beside the original, so that a relative reference the page makes resolves as it would.
        hooked = page_path.resolve().parent / f".{page_path.name}.chromium-check.html"
        hooked.write_text(inject_hook(page), encoding="utf-8")
        try:
            rc, dom, log = run_chromium(chromium, ["--enable-logging=stderr", "--v=0", "--virtual-time-budget=3000",
                                                   "--dump-dom", hooked.as_uri()], workdir)
        finally:
            hooked.unlink(missing_ok=True)
    if rc != 0:
        tail = "\n".join(log.strip().splitlines()[-15:])
        return [f"chromium failed (exit {rc}):\n{tail}"]
    failures = []
    for m in CONSOLE_ERROR.finditer(log):
        failures.append(f"console: {m.group(1)}")
    summary = DomSummary()
    summary.feed(dom)
    root = summary.root_attrs
    if root.get("data-cc-loaded") != "1":
        failures.append("the page never finished loading (or the error hook did not run), so errors could not be checked")
    for e in json.loads(root.get("data-cc-errors") or "[]"):
        failures.append(f"page error: {e}")
    for r in json.loads(root.get("data-cc-resources") or "[]"):
        failures.append(f"the page refers to {r}: it must be self-contained")
    if "js" not in (root.get("class") or "").split():
        failures.append("the page's own script did not run (no class \"js\" on <html>)")
    if summary.matrix_tables != 1 or summary.matrix_rule_rows == 0:
        failures.append(f"no traceability matrix: {summary.matrix_tables} table#matrix, {summary.matrix_rule_rows} rule rows")
    if summary.plots == 0 or summary.plot_paths == 0:
        failures.append(f"no plot: {summary.plots} svg.plot-svg with {summary.plot_paths} paths")
    return list(dict.fromkeys(failures))  # a repeated message once


def screenshot(chromium, page_path: Path, png: Path, window_size: str):
    with tempfile.TemporaryDirectory(prefix="cyclecert-chromium-") as tmp:
        rc, _, log = run_chromium(chromium, ["--hide-scrollbars", f"--window-size={window_size}",
                                             f"--screenshot={png.resolve()}", page_path.resolve().as_uri()], Path(tmp))
    if rc != 0 or not png.exists():
        raise UsageError(f"the screenshot failed (exit {rc}): {log.strip().splitlines()[-1:] }")


# ---- self-test ------------------------------------------------------------------------------------

GOOD_BODY = ('<table id="matrix"><tbody><tr class="rule"><td>G71.OP</td></tr></tbody></table>'
             '<svg class="plot-svg" viewBox="0 0 10 10"><path d="M0 0 L10 10" stroke="black"/></svg>'
             "<script>document.documentElement.classList.add('js');</script>")


def self_test_pages():
    """(name, body, expected failure text or None for a page that must pass)."""
    return [
        ("clean page", GOOD_BODY, None),
        ("a thrown error", GOOD_BODY + "<script>throw new Error('self-test boom');</script>", "self-test boom"),
        ("an error in a timer", GOOD_BODY + "<script>setTimeout(function () { null.f(); }, 50);</script>", "null"),
        ("a syntax error", GOOD_BODY + "<script>var x = ;</script>", "SyntaxError"),
        ("a rejected promise", GOOD_BODY + "<script>Promise.reject(new Error('self-test rejected'));</script>",
         "self-test rejected"),
        ("console.error", GOOD_BODY + "<script>console.error('self-test logged');</script>", "self-test logged"),
        ("a missing image", GOOD_BODY + '<img src="missing-self-test.png" alt="">', "missing-self-test.png"),
        ("a loaded style sheet", GOOD_BODY + '<link rel="stylesheet" href="self-test.css">', "self-test.css"),
        ("no matrix", GOOD_BODY.replace('id="matrix"', 'id="other"'), "no traceability matrix"),
        ("no plot", GOOD_BODY.replace("plot-svg", "other"), "no plot"),
        ("its script not run", GOOD_BODY.replace("document.documentElement.classList.add('js');", ""), "did not run"),
        ("an image in its style", GOOD_BODY + "<style>body { background: url(self-test.png) }</style>", "url("),
    ]


def self_test(chromium):
    problems = []
    with tempfile.TemporaryDirectory(prefix="cyclecert-chromium-self-test-") as tmp:
        folder = Path(tmp)
        (folder / "self-test.css").write_text("body { margin: 0 }\n")
        for i, (name, body, expected) in enumerate(self_test_pages()):
            page = folder / f"page{i}.html"
            page.write_text(f"<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{name}</title></head>"
                            f"<body>{body}</body></html>\n", encoding="utf-8")
            failures = check_page(chromium, page)
            if expected is None and failures:
                problems.append(f"{name}: must pass, but: {'; '.join(failures)}")
            elif expected is not None and not any(expected in f for f in failures):
                problems.append(f"{name}: must be caught (a failure naming '{expected}'), got: {failures or 'no failure'}")
            else:
                print(f"self-test: {name}: {'passes' if expected is None else 'caught: ' + '; '.join(failures)}")
    return problems


# ---- command line ---------------------------------------------------------------------------------

def main(argv):
    parser = argparse.ArgumentParser(description="Check cyclecert's index.html in headless Chromium.")
    parser.add_argument("page", nargs="?", help="the index.html to check")
    parser.add_argument("--render-with", nargs=2, metavar=("RENDER_REPORT", "REPORT_JSON"),
                        help="first write index.html from REPORT_JSON with this program (tests/browser/render_report.cpp)")
    parser.add_argument("--self-test", action="store_true", help="prove that every check can fail")
    parser.add_argument("--chromium", default=DEFAULT_CHROMIUM, help=f"the browser (default {DEFAULT_CHROMIUM})")
    parser.add_argument("--screenshot", metavar="PNG", help="also save a screenshot of the page (unmodified)")
    parser.add_argument("--window-size", default="1400,1800", help="for --screenshot (default 1400,1800)")
    args = parser.parse_args(argv)
    if sum(bool(x) for x in (args.page, args.render_with, args.self_test)) != 1:
        parser.error("give exactly one of INDEX_HTML, --render-with RENDER_REPORT REPORT_JSON, --self-test")

    chromium = shutil.which(args.chromium)
    if not chromium:
        print(f"SKIPPED: chromium not installed ({args.chromium}; Debian: apt-get install chromium)")
        return SKIP

    try:
        if args.self_test:
            problems = self_test(chromium)
            for p in problems:
                print(f"FAIL self-test: {p}")
            print("self-test: " + ("every check can fail" if not problems else f"{len(problems)} problem(s)"))
            return 1 if problems else 0
        with tempfile.TemporaryDirectory(prefix="cyclecert-report-page-") as tmp:
            if args.render_with:
                renderer, report = args.render_with
                page = Path(tmp) / "index.html"
                done = subprocess.run([renderer, report, str(page)], capture_output=True, text=True)
                if done.returncode != 0:
                    raise UsageError(f"{renderer} {report} failed (exit {done.returncode}): {done.stderr.strip()}")
            else:
                page = Path(args.page)
            failures = check_page(chromium, page)
            if args.screenshot:
                screenshot(chromium, page, Path(args.screenshot), args.window_size)
                print(f"screenshot written to {args.screenshot}")
    except UsageError as e:
        print(f"check_report_in_chromium: {e}", file=sys.stderr)
        return 2
    for f in failures:
        print(f"FAIL {f}")
    if failures:
        print(f"{len(failures)} check(s) failed on the page")
        return 1
    print("the page renders in Chromium without errors; the matrix and the plots are present")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
