"""walls.Wall, walls.dumps, walls.from_mesh and walls.read_mesh: each refusal with its
message, numbers read back exactly, dumped files formatted and lint-clean, and meshes
giving the very file `walls-mesh` writes for them (its end-to-end snapshots)."""

import warnings

import numpy as np
import pytest

import walls
from conftest import CASES


def triangle(**more):
    return walls.Wall(
        type="triangle", origin=(0, 0, 0), vertex1=[1, 0, 0], vertex2=(0, 2.5, 0), **more
    )


def test_tokens_are_keyword_arguments_of_any_sequence():
    wall = walls.Wall(
        type="Disc",
        origin=np.array([1.0, 0.5, -2.0]),
        radius=np.float32(0.5),
        color=np.int64(7),
        osc_ampl=2,
        velocity=[0, 0, np.float64(-1)],
    )
    assert wall.type == "disk"
    assert wall.tokens == {
        "type": "disk",
        "origin": (1.0, 0.5, -2.0),
        "radius": 0.5,
        "color": 7,
        "osc-ampl": 2.0,
        "velocity": (0.0, 0.0, -1.0),
    }
    assert wall["osc_ampl"] == 2.0
    assert repr(wall) == (
        "Wall(type='disk', origin=(1, 0.5, -2), radius=0.5, color=7, osc_ampl=2, "
        "velocity=(0, 0, -1))"
    )
    assert wall.set("color", 3.0)["color"] == 3
    assert walls.Wall(type="disc") == walls.Wall(type="disk")
    with pytest.raises(KeyError):
        wall["mass"]


@pytest.mark.parametrize(
    "tokens, error, message",
    [
        ({"raduis": 1}, ValueError, "unknown keyword `raduis`: did you mean `radius`?"),
        (
            {"lengthunit": 1},
            ValueError,
            "`lengthunit` cannot be set in a wall: give the units to dumps, and each wall as a wall of its own",
        ),
        ({"type": "trangle"}, ValueError, "unknown wall type `trangle`: did you mean `triangle`?"),
        ({"radius": [1, 2, 3]}, TypeError, "radius must be a number, not list"),
        ({"radius": True}, TypeError, "radius must be a number, not bool"),
        ({"radius": {}}, TypeError, "radius must be a number, not dict"),
        ({"color": np.bool_(False)}, TypeError, "color must be an integer, not numpy.bool"),
        ({"origin": (1, 2)}, TypeError, "origin must be a sequence of 3 numbers, not a sequence of 2"),
        ({"type": 3}, TypeError, "type must be a wall type name, not int"),
        (
            {"color": 12.5},
            ValueError,
            "color must be an integer, not 12.5 (pkdgrav would read it with atoi, dropping the fraction)",
        ),
        ({"origin": np.array([1, np.nan, 0])}, ValueError, "origin[1] must be a finite number, not nan"),
        ({"radius": float("inf")}, ValueError, "radius must be a finite number, not inf"),
    ],
)
def test_each_mistake_is_refused_with_its_message(tokens, error, message):
    with pytest.raises(error) as raised:
        walls.Wall(**tokens)
    assert type(raised.value) is error
    assert str(raised.value) == message


def test_a_dumped_file_is_formatted_and_clean():
    defaults = walls.Wall(color=3, epsn=0.8)
    text = walls.dumps(
        [triangle(), walls.Wall(type="disk", radius=0.5)],
        units={"lengthunit": 6.68459e-14, "timeunit": 1.99102e-7},
        defaults=defaults,
        comment="A hopper.",
    )
    assert text == (
        "# A hopper.\n"
        "lengthunit 6.68459e-14\n"
        "timeunit 1.99102e-7\n"
        "\n"
        "defaults color 3\n"
        "  epsn 0.8\n"
        "\n"
        "wall type triangle\n"
        "  origin 0 0 0\n"
        "  vertex1 1 0 0\n"
        "  vertex2 0 2.5 0\n"
        "\n"
        "wall type disk\n"
        "  radius 0.5\n"
    )
    assert walls.lint(text) == []
    assert walls.format(text) == text
    # Units by name, and defaults as a dict.
    named = walls.dumps([triangle()], units="cm", defaults={"color": 3})
    assert named.startswith("lengthunit 6.684587122268446e-14\n\ndefaults color 3\n")


def test_numbers_read_back_exactly():
    values = [0.1 + 0.2, 1e-300, 6.68e-14]
    text = walls.dumps([walls.Wall(type="plane", origin=values)])
    assert "origin 0.30000000000000004 1e-300 6.68e-14\n" in text
    assert walls.scene(text)["walls"][0]["origin"] == values


def test_errors_raise_with_their_diagnostics_and_warnings_are_warned():
    crooked = walls.Wall(type="rectangle", vertex1=(1, 0, 0), vertex2=(1, 1, 0))
    with pytest.raises(walls.WallsError) as raised:
        walls.dumps([crooked])
    assert str(raised.value) == (
        "the walls make a file with errors: 3:11: [C106] rectangle wall 0 has vertex1 "
        "and vertex2 at 45.000° (|cos| 0.7071 > 0.001)"
    )
    assert [d["code"] for d in raised.value.diagnostics] == ["C106"]
    with pytest.warns(UserWarning) as warned:
        walls.dumps([walls.Wall(type="triangle", radius=2)])
    assert [str(w.message) for w in warned] == [
        "2:3: warning[C201]: a triangle wall ignores `radius` (`radius 2`)"
    ]
    with pytest.raises(TypeError, match=r"walls\[0\] must be a Wall, not dict"):
        walls.dumps([{"type": "plane"}])
    with pytest.raises(ValueError, match="units must name a length unit"):
        walls.dumps([], units="furlong")


def test_a_mesh_gives_the_file_walls_mesh_writes(case):
    mesh = case("mesh/stl-binary-outward")
    vertices, faces = walls.read_mesh(mesh.dir / "slab.stl")
    wall_list = walls.from_mesh(np.array(vertices), np.array(faces), orientation="outward")
    comment = "Made by walls-mesh from slab.stl: 12 faces as 12 walls, orientation outward."
    assert walls.dumps(wall_list, units="cm", comment=comment) == mesh.stdout()


def test_rectangles_merge_and_orientation_turns_every_face():
    vertices = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    faces = [[0, 3, 2], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
             [2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]]
    merged = walls.from_mesh(vertices, faces, orientation="inward", merge_rectangles=True)
    assert [w.type for w in merged] == ["rectangle"] * 6
    assert merged[0].tokens == {
        "type": "rectangle",
        "origin": (0.0, 1.0, 0.0),
        "vertex1": (0.0, -1.0, 0.0),
        "vertex2": (1.0, 0.0, 0.0),
    }
    # The bottom faces up, into the cube.
    assert np.cross(merged[0]["vertex1"], merged[0]["vertex2"]).tolist() == [0, 0, 1]
    assert walls.lint(walls.dumps(merged)) == []


def test_mesh_mistakes_name_their_place(tmp_path):
    with pytest.raises(walls.WallsError) as raised:
        walls.from_mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], orientation="outward")
    assert str(raised.value) == (
        "face 0: the edge between vertices 0 and 1 belongs to this face only: the mesh is "
        "open, so it has no inside to face; keep the orientation as it is, or close the mesh"
    )
    assert raised.value.diagnostics == []
    with pytest.raises(ValueError, match='orientation must be "keep", "outward" or "inward"'):
        walls.from_mesh([], [], orientation="up")
    with pytest.raises(TypeError, match=r"vertices\[0\] must be a sequence of 3 numbers, not a sequence of 2"):
        walls.from_mesh([(0, 0)], [])
    bad = CASES / "mesh" / "malformed-line" / "bad.obj"
    with pytest.raises(walls.WallsError) as raised:
        walls.read_mesh(bad)
    assert str(raised.value) == f"{bad}:4: `x/1` is not a point's number"
    assert raised.value.diagnostics == []
    box = CASES / "mesh" / "obj-quads" / "box.obj"
    with pytest.warns(UserWarning) as warned:
        vertices, faces = walls.read_mesh(str(box))
    assert [str(w.message) for w in warned] == [
        f"{box}:25: `l` statements are skipped: only points (`v`) and faces (`f`) make walls"
    ]
    assert (len(vertices), len(faces)) == (8, 12)
    assert faces[:2] == [(0, 2, 3), (0, 3, 1)]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(walls.WallsError, match="must end in .stl or .obj"):
            walls.read_mesh(tmp_path / "hull.ply")
