"""Head cameras: a robot's model of them (`hfsm_sim.perception.camera.CameraModel`, built here from
the body profile, the head joints and odometry) and how they render."""

from __future__ import annotations

import math

import numpy as np
import pybullet as p

from hfsm_sim.perception.camera import NEAR, CameraModel, Pose, rot_y, rot_z
from hfsm_sim.profile import CAMERAS, BodyGeometry, CameraSpec
from hfsm_sim.raster import ROOM_LIGHT, Camera

__all__ = ["NEAR", "CameraModel", "TinyRenderer", "camera_model", "camera_spec", "view_matrices",
           "world_camera"]

FAR = 30.0
LIGHT = {"lightDirection": list(ROOM_LIGHT.direction), "lightColor": [1.0, 1.0, 1.0],
         "lightAmbientCoeff": ROOM_LIGHT.ambient, "lightDiffuseCoeff": ROOM_LIGHT.diffuse,
         "lightSpecularCoeff": 0.0}  # ROOM_LIGHT as pybullet's getCameraImage takes it


def camera_model(spec: CameraSpec, body: BodyGeometry, size: tuple[int, int],
                 head_yaw: float, head_pitch: float, odom: Pose = (0.0, 0.0, 0.0)) -> CameraModel:
    width, height = size
    fy = (height / 2) / math.tan(math.radians(spec.vfov_deg) / 2)
    offset = rot_z(head_yaw) @ rot_y(head_pitch) @ np.array([spec.x, 0.0, spec.z])
    position = (float(offset[0]), float(offset[1]), float(body.neck_height + offset[2]))
    return CameraModel(
        camera=spec.name, width=width, height=height, fx=fy, fy=fy, cx=width / 2, cy=height / 2,
        hfov_deg=math.degrees(2 * math.atan((width / 2) / fy)), vfov_deg=spec.vfov_deg,
        position=position, yaw=head_yaw, pitch=head_pitch + math.radians(spec.pitch_deg),
        odom=odom)


def camera_spec(camera: str) -> CameraSpec:
    if camera not in CAMERAS:
        raise ValueError(f"unknown camera {camera!r}; expected one of {sorted(CAMERAS)}")
    return CAMERAS[camera]


def view_matrices(model: CameraModel, base_pos: tuple[float, float, float],
                  base_orn: tuple[float, float, float, float]) -> tuple[list[float], list[float]]:
    """pybullet view and projection matrices for a camera on a body at the given world pose."""
    r_base = np.array(p.getMatrixFromQuaternion(base_orn)).reshape(3, 3)
    eye = np.asarray(base_pos) + r_base @ np.asarray(model.position)
    r_cam = r_base @ model.rotation
    view = p.computeViewMatrix(eye.tolist(), (eye + r_cam[:, 0]).tolist(), r_cam[:, 2].tolist())
    proj = p.computeProjectionMatrixFOV(model.vfov_deg, model.width / model.height, NEAR, FAR)
    return list(view), list(proj)


def world_camera(model: CameraModel, base_pos: tuple[float, float, float],
                 base_orn: tuple[float, float, float, float]) -> Camera:
    """The camera of `model` on a body at the given world pose, as the rasteriser takes it."""
    r_base = np.array(p.getMatrixFromQuaternion(base_orn)).reshape(3, 3)
    eye = np.asarray(base_pos) + r_base @ np.asarray(model.position)
    return Camera(eye, r_base @ model.rotation, model.width, model.height, model.fx, model.fy,
                  model.cx, model.cy, NEAR)


class TinyRenderer:
    """pybullet's tiny renderer (shadows off) behind the rasteriser's interface: what `Rasteriser`
    is checked against, 4-10 times slower (World(renderer="tiny"))."""

    def __init__(self, cid: int) -> None:
        self._cid = cid

    def render(self, camera: Camera, *, segmentation: bool = False
               ) -> tuple[np.ndarray, np.ndarray | None]:
        w, h = camera.width, camera.height
        eye, axes = camera.eye, camera.axes
        view = p.computeViewMatrix(eye.tolist(), (eye + axes[:, 0]).tolist(), axes[:, 2].tolist())
        vfov = math.degrees(2 * math.atan((h / 2) / camera.fy))
        proj = p.computeProjectionMatrixFOV(vfov, w / h, camera.near, FAR)
        flags = 0 if segmentation else p.ER_NO_SEGMENTATION_MASK
        _, _, rgba, _, seg = p.getCameraImage(
            w, h, view, proj, shadow=0, renderer=p.ER_TINY_RENDERER, flags=flags,
            physicsClientId=self._cid, **LIGHT)
        rgb = np.asarray(rgba, dtype=np.uint8).reshape(h, w, 4)[:, :, :3]
        mask = np.asarray(seg, dtype=np.int32).reshape(h, w) if segmentation else None
        return np.ascontiguousarray(rgb), mask
