"""Pictures of 3-D bodies from their VTK faces with matplotlib's 2-D polygons: an orthographic
projection onto a view plane, back faces dropped (each body is convex, so a face turned away from
the viewer is hidden by its own body), the rest painted far to near, each face's colour (the
body's kind) shaded by the angle between its outward normal and a fixed light, so that the
faces of a block read as a solid.

Faces are painted in the order of their farthest corner from the viewer (then of their centre).
That order is right wherever a face Q lies wholly on the viewer's side of a face P's plane and
over P: Q's every point is then nearer than P's farthest corner. Bodies resting on a large table
are that case (the table's top is painted first), where ordering by face centres fails: the
centre of a 5 m table top is nearer to the viewer than the bricks at its far end. The order can
still be wrong between two faces of similar size offset from each other; it shows as a seam.
"""
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import to_rgb

from .figures import KIND_COLOURS

# The light comes from over the viewer's left shoulder (in the camera's frame, so that every view
# has lit faces: a light fixed in the world leaves one elevation in the dark).
LIGHT_IN_CAMERA = np.array([-0.4, 0.5, 0.77]) / np.linalg.norm([-0.4, 0.5, 0.77])  # (right, up, towards)
AMBIENT = 0.35  # the share of a face's colour it keeps when turned away from the light


def view(azimuth_deg, elevation_deg):
    """(right, up, towards the viewer) unit vectors of an orthographic camera whose viewer stands
    at azimuth_deg (from +x towards +y) and elevation_deg above the horizon."""
    az, el = np.radians(azimuth_deg), np.radians(elevation_deg)
    towards = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
    right = np.array([-np.sin(az), np.cos(az), 0.0])
    up = np.cross(towards, right)
    return right, up, towards


# name: (camera, axis labels). The viewer of the axonometric view stands at the front right
# (azimuth -60 deg) and looks down 30 deg.
VIEWS = {
    "axonometric": (view(-60.0, 30.0), ("", "")),
    "plan (from above)": ((np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), np.array([0, 0, 1.0])), ("x [m]", "y [m]")),
    "elevation (from -y)": (view(-90.0, 0.0), ("x [m]", "z [m]")),
    "elevation (from +x)": (view(0.0, 0.0), ("y [m]", "z [m]")),
}


def face_geometry(frame):
    """(outward unit normal, centre) of every face [m], by Newell's sum over its edges; the
    normal is turned away from its body's centre, whatever order the corners come in."""
    p = frame.points_m[frame.connectivity]
    starts, sizes = frame.face_starts(), frame.face_sizes()
    following = np.arange(len(p)) + 1
    following[frame.offsets - 1] = starts  # each face's last corner joins its first
    q = p[following]
    newell = np.add.reduceat(np.cross(p, q), starts, axis=0)
    centre = np.add.reduceat(p, starts, axis=0) / sizes[:, None]
    # Each body's centre as the mean of its face centres: inside a convex body.
    body = frame.face_body()
    count = np.bincount(body).astype(float)
    body_centre = np.stack([np.bincount(body, centre[:, k]) for k in range(3)], axis=1) / np.maximum(count, 1)[:, None]
    outward = np.einsum("ij,ij->i", newell, centre - body_centre[body]) >= 0.0
    normal = np.where(outward[:, None], newell, -newell)
    normal /= np.maximum(np.linalg.norm(normal, axis=1), 1e-300)[:, None]
    return normal, centre


def shaded_colours(normal, kinds_of_faces, camera):
    """RGB of every face: its body's kind colour times ambient + diffuse light."""
    base = np.array([to_rgb(KIND_COLOURS.get(k, "#888888")) for k in kinds_of_faces]).reshape(-1, 3)
    light_direction = np.asarray(camera).T @ LIGHT_IN_CAMERA
    light = AMBIENT + (1.0 - AMBIENT) * np.clip(normal @ light_direction, 0.0, 1.0)
    return base * light[:, None]


def projected_faces(frame, kinds, camera):
    """(polygons in view coordinates [m], their colours) of the faces the viewer sees, far first."""
    right, up, towards = camera
    normal, centre = face_geometry(frame)
    body = frame.face_body()
    visible = normal @ towards > 1e-9
    farthest = np.minimum.reduceat(frame.points_m[frame.connectivity] @ towards, frame.face_starts())
    order = np.lexsort((centre[visible] @ towards, farthest[visible]))
    chosen = np.flatnonzero(visible)[order]
    screen = np.stack([frame.points_m @ right, frame.points_m @ up], axis=1)
    starts, ends = frame.face_starts(), frame.offsets
    polygons = [screen[frame.connectivity[starts[f]:ends[f]]] for f in chosen]
    colours = shaded_colours(normal[chosen], [kinds[b] if b < len(kinds) else "" for b in body[chosen]], camera)
    return polygons, colours


def screen_extent(frame, kinds, camera, only_dynamic=True):
    """(min, max) of the view coordinates [m] of the dynamic bodies' vertices (of all bodies when
    none is dynamic): a 4 m table under a 0.6 m drum would make the drum a speck."""
    right, up, _ = camera
    body = frame.face_body()
    dynamic = np.array([k == "dynamic" for k in kinds])
    faces = np.flatnonzero(dynamic[body]) if only_dynamic and dynamic.any() else np.arange(len(body))
    starts, ends = frame.face_starts(), frame.offsets
    corners = np.unique(np.concatenate([frame.connectivity[starts[f]:ends[f]] for f in faces]))
    screen = np.stack([frame.points_m[corners] @ right, frame.points_m[corners] @ up], axis=1)
    return screen.min(axis=0), screen.max(axis=0)


def draw_frame(ax, frame, kinds, camera, limits, edge_width=0.3):
    """The frame's bodies on ax, seen by camera, within limits ((xmin, ymin), (xmax, ymax)) [m]."""
    polygons, colours = projected_faces(frame, kinds, camera)
    ax.add_collection(PolyCollection(polygons, facecolors=colours, edgecolors="k", linewidths=edge_width))
    (x0, y0), (x1, y1) = limits
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
