"""sim: a headless pybullet world for NAO-sized robots (2 to 16) or light cylinders (up to 50),
blue tables and target points (scenario format: hfsm_sim/README.md, "Teams").

Nothing here imports hfsm or behaviours; pybullet is imported only inside this package.
Each `World` owns its own `p.DIRECT` client (no module-level state); close it when done.

Public API (what the behaviours layer uses)::

    from hfsm_sim import World, load_scenario
    world = World(load_scenario("opposite_long_side"), seed=0,
                  physics_hz=120, image_size=(160, 120),
                  radio_latency=0.1, radio_loss=0.0, success_distance=0.15,
                  recorder=None)               # or hfsm_sim.recorder.Recorder(...)
    world.advance(0.05)                        # step physics for 0.05 s (6 steps at 120 Hz)
    world.time                                 # simulated seconds
    world.robots: dict[str, Robot | LightRobot]  # scenario order; LightRobot (body: light) has
                                               #   only the motion, odometry, battery, bumps
    world.radio: Radio                         # send(sender, to, payload, t) / deliver(t)
    world.score() -> dict                      # success, table_wall_distance, dropped,
                                               # robot_collisions, time, and a few extras
    world.truth                                # ground truth: scorer, recorder, tests ONLY
    world.close()                              # also a context manager

    robot = world.robots["r1"]                 # what a robot commands and senses:
    robot.set_velocity(forward, sideways, turn)  # m/s, m/s (left +), rad/s (ccw +); clamped,
    robot.stop()                               #   held until changed
    robot.set_head(yaw, pitch); robot.head(); robot.head_settled()   # rad; pitch down +
    robot.odometry() -> (x, y, yaw)            # own start frame, seeded drift
    robot.image("forward" | "down") -> np.ndarray  # H x W x 3 uint8 RGB, rendered now
    robot.camera_model(camera) -> CameraModel  # fx, fy, cx, cy, fov, position, yaw, pitch, odom;
                                               #   to_plane(), ground_point(), project(), to_odom()
    robot.arms_lower(); robot.arms_lift(height)  # hand height above the floor, metres
    robot.arms_state() -> ArmState(height, target, settled)
    robot.holding() -> bool                    # the hands carry the table
    robot.hand_load() -> HandLoad(force, left, right)  # body frame: N on both hands,
                                               #   each hand's give (m) off the arm's posture
    robot.bumped() -> bool                     # body touched something in the last advance
    robot.battery() -> float                   # charge 0..1 (scenario `battery:` coefficients)
    robot.battery_empty() -> bool              # the robot fails when it is
    world.fail(name)                           # the robot stops, drops what it holds, goes
                                               #   silent (scenario `failures:`, or the engine)

Scenarios: `scenario_from_dict(data)` validates parsed YAML, `resolve(name_or_path)` finds
a shipped scenario by name or a file by path, `load_scenario(name_or_path)` does both.
The default scenario is `DEFAULT_SCENARIO` ("opposite_long_side").

Pictures: `hfsm_sim.recorder.Recorder(path, every=0.5, cameras=False, view="top"|"3d")` passed as
`World(..., recorder=...)` writes an H.264 MP4 (or VP9 WebM, or GIF) and a final PNG.

The motion, camera and body profile, the lifting rules and the scorer are described in
hfsm_sim/README.md (numbers in hfsm_sim/profile.py).
"""

from hfsm_sim.quiet_import import import_pybullet_quietly

import_pybullet_quietly()  # before any module of this package imports it

from hfsm_sim.camera import CameraModel  # noqa: E402
from hfsm_sim.light import LightRobot  # noqa: E402
from hfsm_sim.radio import Radio  # noqa: E402
from hfsm_sim.robot import ArmState, HandLoad, Robot  # noqa: E402
from hfsm_sim.scenario import (  # noqa: E402
    DEFAULT_SCENARIO,
    Scenario,
    load_scenario,
    resolve,
    scenario_from_dict,
    scenario_names,
)
from hfsm_sim.world import World  # noqa: E402

__all__ = [
    "DEFAULT_SCENARIO",
    "ArmState",
    "CameraModel",
    "HandLoad",
    "LightRobot",
    "Radio",
    "Robot",
    "Scenario",
    "World",
    "load_scenario",
    "resolve",
    "scenario_from_dict",
    "scenario_names",
]
