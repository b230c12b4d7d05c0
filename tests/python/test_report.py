"""bench/report.py: table, totals and problem lists from a results file; valid PNG charts;
malformed input refused with its line number."""
import struct
from pathlib import Path

import pytest

import report
from conftest import FIXTURES, run_script

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
        "report.md", "time_classes.png", "times_sorted.png"]  # no temporary files


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
