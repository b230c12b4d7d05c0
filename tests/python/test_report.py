"""bench/report.py: table, totals and problem lists from a results file; valid PNG charts;
malformed input refused with its line number; report.html beside report.md; with
--thumbnails, a picture per model (bench/render.py, the real arrange: skipped without
$TRITRI_ARRANGE_BIN or build/bin/arrange, failing when CI=true), every one linked, failing
models first, failures to draw noted instead of failing the report."""
import json
import os
import re
import struct
from pathlib import Path

import pytest

import report
from conftest import FIXTURES, REPO, run_script
from report_html import markdown_to_html

SMALL = FIXTURES / "results_small.jsonl"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def small_report(tmp_path_factory):
    """report.py run once, end to end, on the fixture: (report.md text, output folder)."""
    out_dir = tmp_path_factory.mktemp("report") / "rep"
    out = run_script("report.py", SMALL, "--out", out_dir)
    assert out.returncode == 0, out.stderr
    assert "7 models, 3 agree, 1 disagree, 1 error, 1 crash, 1 timeout" in out.stdout
    return (out_dir / "report.md").read_text(), out_dir


def markdown_of(*results):
    records = sorted(report.read_results(results).values(), key=lambda r: r["model"])
    return report.render_markdown(records, [str(r) for r in results], "title", charts=[])


def png_size(path):
    data = Path(path).read_bytes()
    assert data[:8] == PNG_SIGNATURE and data[12:16] == b"IHDR"
    assert data.endswith(b"IEND\xaeB`\x82")  # complete, not a truncated write
    return struct.unpack(">II", data[16:24])


def test_report_table_has_one_row_per_model_with_times_ratios_and_result(small_report):
    md, _ = small_report
    table = md.split(report.MODEL_HEADER + "\n", 1)[1].split("\n\n", 1)[0]
    rows = table.splitlines()[1:]  # after the alignment row
    assert rows == [
        "| bad.stl | 300 | 42 | 0.00300 | 0.00200 | 1.50 | 0.200 | 0.200 | 1.00 | **disagree** |",
        "| boom.off | – | – | – | – | – | – | – | – | crash (SIGSEGV) |",
        "| broken.off | – | – | – | – | – | – | – | – | error (exit 2) |",
        "| cubes.off | 16 | 24 | 0.500 | 0.250 | 2.00 | 1.00 | 0.800 | 1.25 | agree |",
        "| grid.obj | 1089 | 1200 | 0.0200 | 0.0400 | 0.50 | 0.0500 | 0.0500 | 1.00 | agree |",
        "| huge.ply | – | – | – | – | – | – | – | – | time-out (900 s) |",
        # spheres.off timed out first, then a retry agreed: the last line wins.
        "| spheres.off | 5000 | 70000 | 12.5 | 10.0 | 1.25 | 70.0 | 65.0 | 1.08 | agree |",
    ]


def test_report_totals_count_statuses_and_sum_times(small_report):
    md, _ = small_report
    assert "| 7 | 3 | 1 | 1 | 1 | 1 |" in md  # models, agree, disagree, error, crash, timeout
    # Sums over the 4 timed models: 0.5+0.02+0.003+12.5 vs 0.25+0.04+0.002+10.
    assert "| classification | 4 | 13.0 | 10.3 | 1.27 | 1.38 |" in md
    assert "| total | 4 | 71.2 | 66.0 | 1.08 | 1.04 |" in md


def test_report_lists_every_problem_with_its_detail(small_report):
    md, _ = small_report
    assert "## Disagreements (1)\n\n- `bad.stl`\n  - points: 2 points only in native\n" \
           "  - euler: native 2, tritri 0\n" in md
    assert "- `broken.off`: exit code 2: tritri-compare: broken.off: line 3: expected 3 numbers" in md
    assert "- `boom.off`: SIGSEGV: segmentation fault here" in md
    assert "## Time-outs (1)\n\n- `huge.ply`: killed after 902 s" in md


def test_report_charts_are_complete_png_files_and_nothing_else_is_left(small_report):
    md, out_dir = small_report
    for name in ("time_classes.png", "times_sorted.png"):
        width, height = png_size(out_dir / name)
        assert width > 500 and height > 200
        assert f"]({name})" in md
    assert sorted(p.name for p in out_dir.iterdir()) == [
        "report.html", "report.md", "time_classes.png", "times_sorted.png"]  # no temporary files


def test_shard_results_merge_into_the_same_report(tmp_path):
    lines = SMALL.read_text().splitlines(keepends=True)
    first, second = tmp_path / "shard1.jsonl", tmp_path / "shard2.jsonl"
    first.write_text("".join(lines[:4]))
    second.write_text("".join(lines[4:]))
    merged, whole = markdown_of(first, second), markdown_of(SMALL)
    assert merged.split("\n", 3)[3] == whole.split("\n", 3)[3]  # all but the "From" line
    assert "| 7 | 3 | 1 | 1 | 1 | 1 |" in merged


def test_an_empty_results_file_gives_an_empty_report(tmp_path):
    empty = tmp_path / "empty.jsonl"
    empty.write_text("")
    assert report.main([str(empty), "--out", str(tmp_path / "rep")]) == 0
    assert "| 0 | 0 | 0 | 0 | 0 | 0 |" in (tmp_path / "rep" / "report.md").read_text()
    png_size(tmp_path / "rep" / "times_sorted.png")


@pytest.mark.parametrize("bad_line, message", [
    ('{"model": "b.off", "status": "agree"', "malformed results line"),
    ('[1, 2]', "not a JSON object"),
    ('{"status": "agree"}', "no 'model'"),
    ('{"model": "b.off", "status": "fine"}', "'status' is 'fine'"),
])
def test_a_malformed_line_fails_with_its_line_number(tmp_path, bad_line, message):
    results = tmp_path / "bad.jsonl"
    results.write_text('{"model": "a.off", "status": "agree"}\n\n' + bad_line + "\n")
    out = run_script("report.py", results, "--out", tmp_path / "rep")
    assert out.returncode == 2
    assert f"{results}:3: " in out.stderr and message in out.stderr
    assert not (tmp_path / "rep" / "report.md").exists()


def test_a_missing_results_file_fails_clearly(tmp_path):
    out = run_script("report.py", SMALL, tmp_path / "nope.jsonl", "--out", tmp_path / "rep")
    assert out.returncode == 2 and "nope.jsonl: no such results file" in out.stderr


@pytest.mark.parametrize("seconds, label", [
    (0.0, "<0.01 s"), (0.0099, "<0.01 s"), (0.01, "0.01–0.1 s"), (0.5, "0.1–1 s"),
    (1.0, "1–10 s"), (59.9, "10–60 s"), (60.0, ">60 s"), (1e6, ">60 s"),
])
def test_time_classes_are_half_open_intervals(seconds, label):
    assert report.CLASS_LABELS[report.time_class(seconds)] == label


def test_report_html_is_the_markdown_as_a_static_page(small_report):
    md, out_dir = small_report
    page = (out_dir / "report.html").read_text()
    assert page.startswith("<!DOCTYPE html>") and "<script" not in page
    assert '<img src="time_classes.png" alt="models per time class">' in page
    assert page.count("<tr>") == sum(1 for line in md.splitlines()
                                     if line.startswith("|") and not line.startswith("|---"))
    assert "<td><strong>disagree</strong></td>" in page and "<h2>Disagreements (1)</h2>" in page
    assert "thumbs/" not in md and "## Times per model" not in md  # no pictures unless asked


def test_markdown_subset_to_html():
    md = ("# T\n\nA `x|y` & <b> **bold**.\n\n| a | b |\n|---|---:|\n"
          "| `p\\|q` | [![m](t/m.png)](t/m.png) |\n\n- one\n  - two\n- three\n")
    page = markdown_to_html(md, "T & co")
    assert "<title>T &amp; co</title>" in page and "<h1>T</h1>" in page
    assert "<p>A <code>x|y</code> &amp; &lt;b&gt; <strong>bold</strong>.</p>" in page
    assert ('<tr><td><code>p|q</code></td><td class="r"><a href="t/m.png">'
            '<img src="t/m.png" alt="m"></a></td></tr>') in page
    assert "<ul>\n<li>one</li>\n<ul>\n<li>two</li>\n</ul>\n<li>three</li>\n</ul>" in page


# --- thumbnails -------------------------------------------------------------------------------

ARRANGE = Path(os.environ.get("TRITRI_ARRANGE_BIN", str(REPO / "build" / "bin" / "arrange")))


def write_off(path, V, F):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"OFF\n{len(V)} {len(F)} 0\n" + "".join(" ".join(map(str, v)) + "\n" for v in V)
                    + "".join("3 " + " ".join(map(str, f)) + "\n" for f in F))


def record(model, status, total=None, files=None):
    rec = {"model": model, "status": status, "files": files or [model], "wall_s": total or 0.01}
    if total is not None:
        rec["tritri"] = rec["native"] = {"t_classify_s": total / 2, "t_total_s": total}
    return rec


@pytest.fixture(scope="module")
def thumbs_report(tmp_path_factory):
    """report.py --thumbnails on hand-made records of tiny meshes: (report.md, folder)."""
    if not os.access(ARRANGE, os.X_OK):
        if os.environ.get("CI") == "true":
            pytest.fail(f"no arrange binary at {ARRANGE}")
        pytest.skip(f"no arrange binary at {ARRANGE} (set TRITRI_ARRANGE_BIN)")
    base = tmp_path_factory.mktemp("thumbs")
    meshes = base / "meshes"
    flat = ([(0, 0, 0), (4, 0, 0), (0, 4, 0)], [(0, 1, 2)])
    standing = ([(1, 1, -1), (1, 1, 1), (3, -2, 0)], [(0, 1, 2)])
    write_off(meshes / "pair" / "a.off", *flat)
    write_off(meshes / "pair" / "b.off", *standing)
    write_off(meshes / "both.off", flat[0] + standing[0], [(0, 1, 2), (3, 4, 5)])
    write_off(meshes / "slow.off", *flat)
    (meshes / "broken.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    (meshes / "manifest.csv").write_text("file\nboth.off\n")
    records = [
        record("pair/a.off + pair/b.off", "agree", 0.2, ["pair/a.off", "pair/b.off"]),
        record("both.off", "disagree", 0.1),
        record("slow.off", "timeout", files=["slow.off"]),
        record("broken.off", "error"),
        record("gone.off", "agree", 5.0),
        record("sub/both.off", "crash", files=[str((meshes / "both.off").resolve())]),
    ]
    results = base / "r.jsonl"
    results.write_text("".join(json.dumps(r) + "\n" for r in records))
    out_dir = base / "rep"
    (out_dir / "thumbs").mkdir(parents=True)
    (out_dir / "thumbs" / "stale.png").write_bytes(b"old")
    out = run_script("report.py", results, "--out", out_dir, "--thumbnails",
                     meshes / "manifest.csv", "--arrange", ARRANGE, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "pictures in" in out.stderr and "2 models without one" in out.stderr
    return (out_dir / "report.md").read_text(), out_dir


def gallery_rows(md):
    section = md.split("## Models\n", 1)[1].split("\n## ", 1)[0]
    return [l for l in section.splitlines() if l.startswith("| ") and not l.startswith("| picture")]


def test_every_thumbnail_is_linked_and_every_link_exists(thumbs_report):
    md, out_dir = thumbs_report
    files = sorted(p.name for p in (out_dir / "thumbs").iterdir())
    linked = sorted(set(re.findall(r"\]\(thumbs/([^)]+)\)", md)))
    # stale.png removed; gone.off and broken.off have none
    assert files == linked and len(files) == 4
    for name in files:
        assert (out_dir / "thumbs" / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert f'<img src="thumbs/{name}"' in (out_dir / "report.html").read_text()
    assert "pair_a.off_pair_b.off.png" in files


def test_failing_models_come_first_then_the_slowest(thumbs_report):
    md, _ = thumbs_report
    order = [re.search(r"\| `([^`]+)` \|", row).group(1) for row in gallery_rows(md)]
    assert order == ["both.off", "sub/both.off", "broken.off", "slow.off", "gone.off",
                     "pair/a.off + pair/b.off"]
    assert md.index("## Models") < md.index("## Times per model") and report.MODEL_HEADER in md


def test_counts_and_failures_to_draw_are_noted(thumbs_report):
    md, _ = thumbs_report
    rows = {re.search(r"\| `([^`]+)` \|", r).group(1): r for r in gallery_rows(md)}
    assert rows["pair/a.off + pair/b.off"].endswith("| agree | – | – | 8 | 1 | 0.200 |  |")
    assert "| **disagree** |" in rows["both.off"] and "| 8 | 1 |" in rows["both.off"]
    assert "input only: the run timed out" in rows["slow.off"]
    assert "(thumbs/slow.off.png)" in rows["slow.off"]
    assert "no picture: arrange exit 1" in rows["broken.off"]
    assert rows["broken.off"].startswith("| – |")
    assert "no picture: no such file" in rows["gone.off"]
    assert "(thumbs/sub_both.off.png)" in rows["sub/both.off"]  # an absolute file label


def test_gallery_order_without_pictures():
    recs = [record("a", "agree", 1.0), record("b", "agree", 2.0), record("c", "timeout"),
            record("d", "disagree", 0.5), record("e", "crash"), record("f", "error")]
    assert [r["model"] for r in report.gallery_order(recs)] == ["d", "e", "f", "c", "b", "a"]
    taken = set()
    assert [report.thumb_name(m, taken) for m in ("a/b.off", "a_b.off", "A_B.off", "..")] == [
        "a_b.off.png", "a_b.off-2.png", "A_B.off-3.png", "model.png"]


def test_thumbnails_need_the_meshes_and_arrange(tmp_path, capsys):
    results = tmp_path / "r.jsonl"
    results.write_text(json.dumps(record("a.off", "agree", 1.0)) + "\n")
    for extra, message in ((["--thumbnails", str(tmp_path / "none")], "--thumbnails"),
                           (["--thumbnails", str(tmp_path), "--arrange", str(tmp_path / "no")],
                            "--arrange")):
        with pytest.raises(SystemExit) as e:
            report.main([str(results), "--out", str(tmp_path / "rep"), *extra])
        assert e.value.code == 2 and message in capsys.readouterr().err
    assert not (tmp_path / "rep").exists()
