"""bench/compare_upstream.py: the fan-triangulated variants are fed to us as fans."""
import compare_upstream


def test_fan_splits_every_polygon_from_its_first_corner(tmp_path):
    src = tmp_path / "poly.off"
    src.write_text("OFF\n# a comment\n7 2 0\n" + "".join(f"{i} {i * i} 0\n" for i in range(7)) +
                   "7 0 6 5 4 3 2 1\n3 1 2 3\n")
    out = tmp_path / "fan.off"
    compare_upstream.fan_triangulated_off(src, out)
    lines = out.read_text().split("\n")
    assert lines[:2] == ["OFF", "7 6 0"]
    assert lines[2:9] == [f"{i} {i * i} 0" for i in range(7)]
    assert lines[9:15] == ["3 0 6 5", "3 0 5 4", "3 0 4 3", "3 0 3 2", "3 0 2 1", "3 1 2 3"]


def test_fan_refuses_what_is_not_off(tmp_path):
    src = tmp_path / "poly.obj"
    src.write_text("v 0 0 0\n")
    try:
        compare_upstream.fan_triangulated_off(src, tmp_path / "x.off")
    except ValueError as e:
        assert "OFF" in str(e)
    else:
        raise AssertionError("a non-OFF file was accepted")
