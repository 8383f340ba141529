"""blockdem.Scenario: reading, the CLI's checks and messages, and edits from Python."""
import numpy as np
import pytest

import blockdem
from conftest import block_on_table

BAD_WIDTH = """
[simulation]
duration = 0.1
dt = 1e-5
[[bodies]]
name = "b1"
kind = "dynamic"
shape = "rectangle"
width = -1
height = 1
center = [0, 0.5]
"""


def test_from_file_reads_an_example(source_dir):
    s = blockdem.Scenario.from_file(source_dir / "examples/paper/sliding.toml")
    assert s.file.endswith("sliding.toml")
    assert s.to_dict()["contact"]["mu"] == 0.3


def test_missing_file_is_an_input_error(tmp_path):
    with pytest.raises(blockdem.InputError) as e:
        blockdem.Scenario.from_file(tmp_path / "none.toml")
    assert e.value.file == str(tmp_path / "none.toml")
    assert "cannot open" in str(e.value)


def test_input_error_names_file_key_line_and_body():
    with pytest.raises(blockdem.InputError) as e:
        blockdem.Scenario.from_toml(BAD_WIDTH)
    err = e.value
    assert isinstance(err, ValueError)
    assert (err.file, err.key, err.line, err.body) == ("<toml>", "bodies.b1.width", 9, "b1")
    # The CLI's message, word for word.
    assert str(err) == "<toml>:9:9: key 'bodies.b1.width': must be > 0, got -1"


def test_toml_syntax_error_has_its_line():
    with pytest.raises(blockdem.InputError) as e:
        blockdem.Scenario.from_toml("[simulation]\nduration = = 1\n")
    assert e.value.line == 2 and "TOML syntax error" in str(e.value)


def test_from_dict_checks_as_the_cli():
    s = blockdem.Scenario.from_dict(block_on_table())
    assert [b["name"] for b in s.to_dict()["bodies"]] == ["table", "block"]
    bad = block_on_table()
    bad["contact"]["mu"] = -0.1
    with pytest.raises(blockdem.InputError) as e:
        blockdem.Scenario.from_dict(bad)
    assert e.value.key == "contact.mu" and e.value.file == "<dict>" and e.value.body is None


@pytest.mark.parametrize("value", [None, object(), {1, 2}])
def test_from_dict_refuses_values_toml_cannot_hold(value):
    bad = block_on_table()
    bad["contact"]["mu"] = value
    with pytest.raises(TypeError, match="contact.mu"):
        blockdem.Scenario.from_dict(bad)


def test_from_dict_refuses_nan():
    bad = block_on_table()
    bad["contact"]["kn"] = float("nan")
    with pytest.raises(ValueError, match="contact.kn"):
        blockdem.Scenario.from_dict(bad)


def test_set_is_the_clis_set_and_a_failed_edit_changes_nothing():
    s = blockdem.Scenario.from_dict(block_on_table())
    s.set("contact.mu", 0.6)
    s.set("bodies.block.width", np.float64(0.4))
    d = s.to_dict()
    assert d["contact"]["mu"] == 0.6 and d["bodies"][1]["width"] == 0.4
    with pytest.raises(blockdem.InputError) as e:
        s.set("bodies.block.height", -2.0)
    assert e.value.body == "block"
    assert s.to_dict()["bodies"][1]["height"] == 0.2


def test_bodies_and_contact_edits():
    s = blockdem.Scenario.from_dict(block_on_table())
    s.add_body({"name": "top", "kind": "dynamic", "shape": "rectangle", "width": 0.2, "height": 0.2,
                "center": [0.0, 0.3], "density": 2000.0})
    assert len(s.to_dict()["bodies"]) == 3
    s.remove_body("top")
    with pytest.raises(KeyError, match="nobody"):
        s.remove_body("nobody")
    s.set_contact({"mu": 0.45, "h_s": 0.5})
    assert s.to_dict()["contact"]["mu"] == 0.45
    with pytest.raises(blockdem.InputError):  # overlaps the block at the start
        s.add_body({"name": "inside", "kind": "dynamic", "shape": "rectangle", "width": 0.2, "height": 0.2,
                    "center": [0.0, 0.1], "density": 2000.0})


def test_motion_from_a_numpy_array():
    s = blockdem.Scenario.from_dict(block_on_table())
    a = 3.5 * np.cos(2 * np.pi * np.arange(0, 2.0, 0.01))
    s.set_motion(a, dt=0.01)
    m = s.to_dict()["table_motion"]["horizontal"]
    assert m["type"] == "series" and len(m["values"]) == len(a) and m["dt"] == 0.01
    s.set_motion(motion={"type": "sine", "amplitude": 1.0, "period": 0.5}, direction="vertical")
    assert s.to_dict()["table_motion"]["vertical"]["type"] == "sine"


def test_motion_array_errors():
    s = blockdem.Scenario.from_dict(block_on_table())
    a = np.zeros(50)
    a[7] = np.nan
    with pytest.raises(ValueError, match="sample 7"):
        s.set_motion(a, dt=0.01)
    with pytest.raises(ValueError, match="1-D"):
        s.set_motion(np.zeros((10, 2)), dt=0.01)
    with pytest.raises(TypeError, match="dt"):
        s.set_motion(np.zeros(10))
    with pytest.raises(TypeError):
        s.set_motion("not numbers", dt=0.01)
    with pytest.raises(blockdem.InputError, match="dt"):
        s.set_motion(np.zeros(10), dt=-1.0)
    with pytest.raises(ValueError, match="direction"):
        s.set_motion(np.zeros(10), dt=0.01, direction="sideways")
    assert "table_motion" not in s.to_dict()


def test_motion_constructors_refuse_what_the_scenario_refuses():
    # A motion starts at rest at start >= 0, as the scenario's `start` key; an amplitude beyond
    # 1e4 m/s^2 is a wrong unit (io/scenario_keys.hpp), as is one that overflows.
    with pytest.raises(ValueError, match="start must be >= 0"):
        blockdem.Motion.sine(1.0, 0.5, start=-5.0)
    with pytest.raises(ValueError, match="start must be >= 0"):
        blockdem.Motion.one_sine(1.0, 0.5, start=float("nan"))
    with pytest.raises(ValueError, match="start must be >= 0"):
        blockdem.Motion.series(np.zeros(10), 0.01, start=-0.1)
    with pytest.raises(ValueError, match="beyond the 10000 m/s"):
        blockdem.Motion.one_cosine(2e4, 0.5)
    with pytest.raises(ValueError, match="beyond the 10000 m/s"):
        blockdem.Motion.ricker(float("inf"), 2.0)
    with pytest.raises(ValueError, match="beyond the 10000 m/s"):
        blockdem.Motion.series(np.array([0.0, 3e4, 0.0]), 0.01)
    with pytest.raises(ValueError, match="cycles"):
        blockdem.Motion.sine(1.0, 0.5, cycles=-1.0)
    assert blockdem.Motion.sine(9.81, 0.5, start=0.2, cycles=2.0).sample(0.2)["acceleration"] == 0.0
