"""The robots' camera images: the world's boxes and cylinders drawn into a numpy depth buffer.

Every visible body of the world is a set of boxes (hfsm_sim.room, hfsm_sim.body) or a cylinder
(hfsm_sim.light) of one colour each. This draws them as pybullet's tiny renderer does (its flat light: ambient
plus diffuse, no specular, no shadows; its colours to the unit; its sampling of pixel (i, j) at
image point (i, j + 1); a white sky) at a fraction of its cost, which grows with every pixel a
surface covers (~250 ns a pixel, 50-100 ms an image at 640x480). The two differ on the odd pixel
along an edge (tests/sim/test_raster.py), and on cylinders: 32 flat sides here, the same
silhouette and hue, where the tiny renderer shades them smoothly. Each face seen from the front
is cut at the near plane; its pixels are, row by row, the span between its edges, kept where it
is nearer than what is drawn (a plane's inverse depth is affine in the image: one broadcast sum
a face).

Why not a library: pybullet's other renderer, pyrender, moderngl and Open3D need an OpenGL
context (EGL or OSMesa from the system, not from pip) and light and sample otherwise, so the
robots would see other pictures; OpenCV's `fillConvexPoly` fills by pixel area, not at points,
which moved every edge by half a pixel (1-2 % of the pixels of an image).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

import numpy as np
import pybullet as p

SKY = (255, 255, 255)
# A box's corners (signs of x, y, z) and its faces, four corners each, with their outward normals.
_SIGNS = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
_FACES = np.array([[4, 6, 7, 5], [0, 1, 3, 2], [2, 3, 7, 6], [0, 4, 5, 1], [1, 5, 7, 3],
                   [0, 2, 6, 4]])
_NORMALS = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)
SIDES = 32  # a cylinder is drawn as a prism of this many flat sides (the tiny renderer's count)


@dataclass(frozen=True)
class Light:
    """A directional light as the tiny renderer takes it (its `lightDirection` points to it)."""

    direction: tuple[float, float, float]
    ambient: float
    diffuse: float


ROOM_LIGHT = Light((0.4, 0.3, 1.0), ambient=0.65, diffuse=0.35)


@dataclass(frozen=True)
class Camera:
    """A pinhole camera in the world: its eye, its axes (columns: forward, left, up), intrinsics
    in pixels as hfsm_sim.camera.CameraModel has them, and the near plane."""

    eye: np.ndarray
    axes: np.ndarray
    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    near: float


class Renderer(Protocol):
    def render(self, camera: Camera, *, segmentation: bool = False
               ) -> tuple[np.ndarray, np.ndarray | None]: ...


@dataclass(frozen=True)
class _Part:
    """The faces of one link of a body (-1: its base), in that link's frame."""

    body: int
    link: int
    quads: np.ndarray  # faces x 4 corners x 3 (a face of fewer corners repeats its last)
    normals: np.ndarray  # faces x 3, outward
    base_colours: np.ndarray  # faces x 3: the shape's colour on a white texture, 0..255


def _box(size: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return (_SIGNS * size / 2)[_FACES], _NORMALS


def _cylinder(length: float, radius: float) -> tuple[np.ndarray, np.ndarray]:
    """A prism of SIDES flat sides about z, its two caps cut into quads fanned from one corner."""
    angle = 2 * math.pi * np.arange(SIDES) / SIDES
    ring = np.stack([radius * np.cos(angle), radius * np.sin(angle)], axis=1)
    low, high = (np.column_stack([ring, np.full(SIDES, z)]) for z in (-length / 2, length / 2))
    nxt = np.roll(np.arange(SIDES), -1)
    sides = np.stack([low, low[nxt], high[nxt], high], axis=1)
    middle = angle + math.pi / SIDES
    side_normals = np.column_stack([np.cos(middle), np.sin(middle), np.zeros(SIDES)])
    fan = [[0, i, min(i + 1, SIDES - 1), min(i + 2, SIDES - 1)] for i in range(1, SIDES - 1, 2)]
    caps = np.concatenate([high[fan], low[fan]])
    cap_normals = np.repeat([[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]], len(fan), axis=0)
    return np.concatenate([sides, caps]), np.concatenate([side_normals, cap_normals])


def scene_parts(cid: int) -> list[_Part]:
    """The faces of every body of the client, grouped by link: boxes and cylinders. Spheres are
    skipped: the only one is the small sphere pybullet shows at a robot's neck, hidden inside it."""
    groups: dict[tuple[int, int], tuple[list[np.ndarray], list[np.ndarray], list[np.ndarray]]] = {}
    for index in range(p.getNumBodies(physicsClientId=cid)):
        body = p.getBodyUniqueId(index, physicsClientId=cid)
        for shape in p.getVisualShapeData(body, physicsClientId=cid):
            if shape[7][3] == 0.0:
                continue
            if shape[2] == p.GEOM_BOX:
                quads, normals = _box(np.asarray(shape[3]))
            elif shape[2] == p.GEOM_CYLINDER:
                quads, normals = _cylinder(shape[3][0], shape[3][1])
            else:
                continue
            rot = np.array(p.getMatrixFromQuaternion(shape[6])).reshape(3, 3)
            faces, outward, colours = groups.setdefault((body, shape[1]), ([], [], []))
            faces.append(quads @ rot.T + np.asarray(shape[5]))
            outward.append(normals @ rot.T)
            colour = np.floor(np.float32(255.0) * np.asarray(shape[7][:3], np.float32))
            colours.append(np.broadcast_to(colour, (len(quads), 3)))
    return [_Part(body, link, np.concatenate(q), np.concatenate(n), np.concatenate(c))
            for (body, link), (q, n, c) in groups.items()]


Placed = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]  # faces' corners, normals, colours, bodies


class Rasteriser:
    """Draws camera views of one pybullet client's boxes; reads the scene again when a body is
    added or removed. `clock` (the world's physics step count): the faces placed in the world are
    kept for every image drawn until it moves on (the robots of a room look in the same tick)."""

    def __init__(self, cid: int, light: Light = ROOM_LIGHT, clock: Callable[[], int] | None = None) -> None:
        self._cid = cid
        direction = np.asarray(light.direction, float)
        self._light = direction / np.linalg.norm(direction)
        self._ambient, self._diffuse = np.float32(light.ambient), np.float32(light.diffuse)
        self._bodies = -1
        self._parts: list[_Part] = []
        self._clock = clock
        self._placed: tuple[int, Placed] | None = None

    def _scene(self) -> list[_Part]:
        bodies = p.getNumBodies(physicsClientId=self._cid)
        if bodies != self._bodies:
            self._parts, self._bodies = scene_parts(self._cid), bodies
        return self._parts

    def _world(self) -> Placed:
        """Every face in the world frame now: corners (F x 4 x 3), normals (F x 3), base colours and
        body ids; placed once a physics step when there is a clock."""
        if self._clock is None:
            return self._place()
        now, placed = self._clock(), self._placed
        if placed is None or placed[0] != now or self._bodies != p.getNumBodies(physicsClientId=self._cid):
            placed = self._placed = (now, self._place())
        return placed[1]

    def _place(self) -> Placed:
        quads, normals, colours, bodies = [], [], [], []
        for part in self._scene():
            if part.link < 0:
                pos, orn = p.getBasePositionAndOrientation(part.body, physicsClientId=self._cid)
            else:
                pos, orn = p.getLinkState(part.body, part.link, physicsClientId=self._cid)[:2]
            rot = np.array(p.getMatrixFromQuaternion(orn)).reshape(3, 3)
            quads.append(part.quads @ rot.T + pos)
            normals.append(part.normals @ rot.T)
            colours.append(part.base_colours)
            bodies.append(np.full(len(part.quads), part.body))
        return np.concatenate(quads), np.concatenate(normals), np.concatenate(colours), np.concatenate(bodies)

    def _faces(self, camera: Camera) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Every face seen from the front: corners in the camera frame (F x 4 x 3), normals in the
        camera frame (F x 3), colours (F x 3 uint8) and body ids (F)."""
        world, normal, colours, bodies = self._world()
        front = np.einsum("fk,fk->f", world[:, 0] - camera.eye, normal) < 0.0
        lit = self._shade(normal[front], colours[front])
        return ((world[front] - camera.eye) @ camera.axes, normal[front] @ camera.axes, lit, bodies[front])

    def _shade(self, normals: np.ndarray, base: np.ndarray) -> np.ndarray:
        """The tiny renderer's colour of each face: int(ambient * c + diffuse * max(0, n.l) * c)."""
        lambert = np.maximum(0.0, normals @ self._light).astype(np.float32)[:, None]
        colour = self._ambient * base + self._diffuse * lambert * base
        return np.asarray(np.minimum(colour, 255), dtype=np.uint8)

    def render(self, camera: Camera, *, segmentation: bool = False
               ) -> tuple[np.ndarray, np.ndarray | None]:
        """RGB (H x W x 3 uint8); and the body-id mask (-1: sky), if asked."""
        w, h = camera.width, camera.height
        corners, normals, colours, bodies = self._faces(camera)
        u, v, seen = _project(corners, camera)
        corners, normals, u, v = corners[seen], normals[seen], u[seen], v[seen]
        first, last, rows = _spans(u, v, w, h)
        depth = np.zeros((h, w), np.float32)  # inverse depth along the view; 0: nothing yet
        drawn = np.zeros((h, w), np.int32)  # which face each pixel shows, 0: the sky
        # the ray through the image point of pixel (i, j), (i, j + 1), is (1, ray_u[i], ray_v[j])
        # in the camera's axes
        ray_u = ((camera.cx - np.arange(w)) / camera.fx).astype(np.float32)
        ray_v = ((camera.cy - np.arange(1, h + 1)) / camera.fy).astype(np.float32)
        index = np.flatnonzero(seen) + 1
        for f in np.flatnonzero(rows.any(axis=1)):
            y0 = int(np.argmax(rows[f]))
            y1 = h - int(np.argmax(rows[f, ::-1]))
            lo, hi = first[f, y0:y1, None], last[f, y0:y1, None]
            x0, x1 = int(lo.min()), int(hi.max()) + 1
            cols = np.arange(x0, x1)
            # points X of the face: n . X = d; along a ray r, X = r / inv with inv = (n . r) / d
            n, d = normals[f], float(normals[f] @ corners[f, 0])
            inv = (n[2] / d) * ray_v[y0:y1, None] + ((n[0] + n[1] * ray_u[x0:x1]) / d)[None, :]
            inside = (cols >= lo) & (cols <= hi) & (inv > depth[y0:y1, x0:x1])
            np.copyto(depth[y0:y1, x0:x1], inv, where=inside)
            np.copyto(drawn[y0:y1, x0:x1], index[f], where=inside)
        palette = np.concatenate([np.array([SKY], np.uint8), colours])
        mask = np.concatenate([[-1], bodies]).astype(np.int32)[drawn] if segmentation else None
        return palette[drawn], mask


def _project(corners: np.ndarray, camera: Camera) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Image points (u, v: F x 5, row j sampling v = j) of the faces cut at the near plane, a
    quad's last corner repeated; and which faces may show in the image."""
    ahead = corners[:, :, 0] >= camera.near
    pts = corners[:, [0, 1, 2, 3, 3]]
    for f in np.flatnonzero(ahead.any(axis=1) & ~ahead.all(axis=1)):
        cut = _clip_near(corners[f], camera.near)
        pts[f] = np.concatenate([cut, cut[-1:].repeat(5 - len(cut), 0)])
    with np.errstate(divide="ignore", invalid="ignore"):
        u = camera.cx - camera.fx * pts[:, :, 1] / pts[:, :, 0]
        v = camera.cy - camera.fy * pts[:, :, 2] / pts[:, :, 0] - 1.0
    seen = ahead.any(axis=1)
    seen &= (u.max(axis=1) >= 0) & (u.min(axis=1) <= camera.width - 1)
    seen &= (v.max(axis=1) >= 0) & (v.min(axis=1) <= camera.height - 1)
    return u, v, seen


def _spans(u: np.ndarray, v: np.ndarray, w: int, h: int
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The pixels convex polygons (image points u, v of their corners, in order: F x K) cover,
    sampled as the tiny renderer samples, pixel (i, j) at point (i, j), edges included: for each
    polygon and row the first and last column, and whether the row has any (F x H each)."""
    du, dv = np.roll(u, -1, axis=1) - u, np.roll(v, -1, axis=1) - v
    sign = np.sign(np.sum(u * np.roll(v, -1, axis=1) - np.roll(u, -1, axis=1) * v, axis=1))
    # inside edge k: sign * (du_k (y - v_k) - dv_k (x - u_k)) >= 0, i.e. a_k x <= b_k(y)
    a = (sign[:, None] * dv)[:, None, :]
    y = np.arange(h, dtype=np.float64)[None, :, None]
    b = sign[:, None, None] * (du[:, None, :] * (y - v[:, None, :]) + (dv * u)[:, None, :])
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # inf: clipped below
        bound = b / a
    lo = np.max(np.where(a < 0, bound, -np.inf), axis=2)
    hi = np.min(np.where(a > 0, bound, np.inf), axis=2)
    # clipped both ways before the cast: a near-horizontal edge gives bounds past int64 (1e190)
    first = np.clip(np.ceil(lo), 0, w).astype(np.int64)
    last = np.clip(np.floor(hi), -1, w - 1).astype(np.int64)
    rows = (first <= last) & ~np.any((a == 0) & (b < 0), axis=2) & (sign != 0)[:, None]
    return first, last, rows


def _clip_near(points: np.ndarray, near: float) -> np.ndarray:
    """The polygon (camera frame, x forward) cut to x >= near (Sutherland-Hodgman, one plane)."""
    out = []
    for a, b in zip(points, np.roll(points, -1, axis=0), strict=True):
        if a[0] >= near:
            out.append(a)
        if (a[0] >= near) != (b[0] >= near):
            out.append(a + (near - a[0]) / (b[0] - a[0]) * (b - a))
    return np.array(out)
