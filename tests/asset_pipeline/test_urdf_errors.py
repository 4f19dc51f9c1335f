"""Malformed URDF files: one-line errors naming the file and the element, exit code 2, nothing
written; and a fuzz of the URDF reader (it raises FormatError or reads, nothing else)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from asset_pipeline.urdf import parse_urdf, read_urdf
from holomj.cli.app import app
from holomj.errors import FormatError
from tests.asset_pipeline.urdf_helpers import write_partnet_cabinet

CYCLE = (
    '<parent link="base"/>\n\t</joint>\n</robot>',
    '<parent link="link_0"/>\n\t</joint>\n</robot>',
)
BROKEN = {
    "missing_mesh": (
        ("original-2.obj", "missing.obj"),
        r"link 'link_0' \(line \d+\) visual 0 \(line \d+\): mesh 'textured_objs/missing.obj': "
        r"mesh file not found",
    ),
    "bad_joint_type": (
        ('type="revolute"', 'type="hinge"'),
        r"joint 'joint_0' \(line \d+\): joint type 'hinge' is unknown",
    ),
    "floating_joint": (
        ('type="prismatic"', 'type="floating"'),
        r"joint 'joint_1' \(line \d+\): joint type 'floating' is not supported",
    ),
    "cycle": (CYCLE, r"joints form a cycle through links"),
    "two_parents": (
        ('<child link="link_1"/>', '<child link="link_0"/>'),
        r"link 'link_0' has two parent joints, 'joint_0' and 'joint_1'",
    ),
    "unknown_link": (('<parent link="link_2"/>', '<parent link="link_9"/>'), r"'link_9' is not"),
    "no_limit": (('<limit lower="-1.9" upper="0.0"/>', ""), r"joint 'joint_0'.*needs <limit"),
    "bad_number": (('axis xyz="0 0 1"', 'axis xyz="0 0 x"'), r"xyz='0 0 x'.*is not 3 numbers"),
    "zero_axis": (('axis xyz="0 0 1"', 'axis xyz="0 0 0"'), r"joint 'joint_1'.*the axis is zero"),
    "not_xml": (("</robot>", "</robt>"), r"not well-formed XML: mismatched tag at line \d+"),
    "dae_mesh": (("original-3.obj", "original-3.dae"), r"mesh format '.dae' is not supported"),
}


@pytest.fixture(scope="module")
def model(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The valid cabinet (box knob), written once."""
    return write_partnet_cabinet(tmp_path_factory.mktemp("valid") / "cabinet")


def _broken(model: Path, target: Path, old: str, new: str) -> Path:
    """A copy of the cabinet's folder with ``old`` replaced by ``new`` in its URDF."""
    target.mkdir(parents=True)
    text = model.read_text()
    assert old in text, old
    for item in model.parent.rglob("*"):
        dest = target / item.relative_to(model.parent)
        if item.is_dir():
            dest.mkdir(exist_ok=True)
        else:
            dest.write_bytes(item.read_bytes())
    path = target / model.name
    path.write_text(text.replace(old, new, 1))
    return path


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_a_malformed_urdf_is_refused_with_one_line_and_nothing_written(
    model: Path, tmp_path: Path, case: str
) -> None:
    (old, new), pattern = BROKEN[case]
    path = _broken(model, tmp_path / case, old, new)
    library = tmp_path / "library"
    result = CliRunner().invoke(
        app, ["assets", "import", str(path), "--library", str(library), "--no-thumbnails"]
    )
    assert result.exit_code == 2, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: {path}: "), result.output
    assert re.search(pattern, lines[0]), lines[0]
    assert not library.exists()  # checked before anything is written


def test_a_malformed_urdf_in_a_folder_stops_the_import_before_writing(
    model: Path, tmp_path: Path
) -> None:
    good = tmp_path / "models" / "good"
    _broken(model, good, "<robot", "<robot")
    bad = _broken(model, tmp_path / "models" / "bad", 'type="revolute"', 'type="spherical"')
    library = tmp_path / "library"
    result = CliRunner().invoke(
        app, ["assets", "import", str(tmp_path / "models"), "--library", str(library)]
    )
    assert result.exit_code == 2 and str(bad) in result.output
    assert not library.exists()


def test_the_reader_reads_the_valid_model(model: Path) -> None:
    urdf = read_urdf(model)
    assert urdf.roots == ["base"] and [j.name for j in urdf.joints] == [
        "joint_2",
        "joint_0",
        "joint_1",
    ]
    assert len(urdf.files()) == 4  # carcass, door, knob, drawer


_TAGS = ["robot", "link", "joint", "visual", "geometry", "mesh", "box", "origin", "axis",
         "limit", "parent", "child", "material", "color", "xacro:macro", "dynamics"]  # fmt: skip
_ATTRS = ["name", "type", "link", "xyz", "rpy", "filename", "size", "lower", "upper", "rgba",
          "scale", "radius", "length", "damping"]  # fmt: skip
_VALUES = st.one_of(
    st.sampled_from(["revolute", "continuous", "prismatic", "fixed", "floating", "base", "link_0",
                     "link_1", "link_2", "0 0 1", "1 2", "nan", "1e999", "-1", "", "a b c",
                     "textured_objs/original-1.obj", "../x.obj", "package://p/x.obj"]),
    st.text(max_size=12),
)  # fmt: skip


def _element(draw, depth: int) -> str:
    tag = draw(st.sampled_from(_TAGS))
    attrs = draw(st.dictionaries(st.sampled_from(_ATTRS), _VALUES, max_size=3))
    text = " ".join(f'{k}="{_escape(v)}"' for k, v in attrs.items())
    children = []
    if depth > 0:
        children = [_element(draw, depth - 1) for _ in range(draw(st.integers(0, 3)))]
    return f"<{tag} {text}>{''.join(children)}</{tag}>"


def _escape(value: str) -> str:
    return value.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")


@st.composite
def urdf_documents(draw) -> str:
    """Random robot-shaped XML: known tags and attributes with good and bad values."""
    body = "".join(_element(draw, 2) for _ in range(draw(st.integers(0, 5))))
    return f'<robot name="fuzz">{body}</robot>'


@settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(document=urdf_documents())
def test_fuzz_structured_urdf(model: Path, document: str) -> None:
    _reads_or_refuses(document, model)


@settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(cut=st.integers(0, 4000), junk=st.text(max_size=20))
def test_fuzz_mangled_cabinet(model: Path, cut: int, junk: str) -> None:
    text = model.read_text()
    cut = min(cut, len(text))
    _reads_or_refuses(text[:cut] + junk + text[cut:], model)


@settings(max_examples=100, deadline=None)
@given(data=st.binary(max_size=200))
def test_fuzz_bytes(data: bytes) -> None:
    _reads_or_refuses(data, Path("/nonexistent/fuzz.urdf"))


def _reads_or_refuses(document: str | bytes, model: Path) -> None:
    try:
        urdf = parse_urdf(document, model)
    except FormatError as err:
        message = str(err)
        assert "\n" not in message and str(model) in message
        return
    for joint in urdf.joints:  # what it reads is a checked tree
        assert joint.parent in urdf.links and joint.child in urdf.links
        if joint.limit is not None:
            assert joint.limit[0] < joint.limit[1]
    for link in urdf.links.values():
        for geometry in link.geometry:
            assert geometry.mesh is None or geometry.mesh.is_file()
