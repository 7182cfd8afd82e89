"""The inputs the sim world declares (docs/REFERENCE.md#watches): what machines read as `in.NAME`.

Declarations only, so that `hfsm-run --check` knows them without starting the simulator; the
values come from `hfsm_behaviours.senses`, from what a robot senses (`radio_delay` from what its radio
hears, in `hfsm_behaviours.simworld`).
"""

from __future__ import annotations

from collections.abc import Mapping

from hfsm.world import InputSpec

SIM_INPUTS: Mapping[str, InputSpec] = {
    spec.name: spec
    for spec in (
        InputSpec("table_in_view", "bool", "the blue table is in the forward camera's image"),
        InputSpec(
            "table_bearing",
            "float",
            "degrees, left positive, body frame (head turn included): the direction of the table "
            "blob's centre in the forward image; null when the table is not in view",
        ),
        InputSpec(
            "table_distance",
            "float",
            "metres on the floor to the table blob's lowest pixel (its nearest foot); null when the "
            "table is not in view or its lowest pixel is above the horizon",
        ),
        InputSpec(
            "tables_in_view",
            "list",
            "every table top in the forward image, told apart, nearest first: [{x, y: metres, the "
            "top's centre in the frame of in.pose, heading: degrees of its long axis (-90..90], "
            "length, width: metres, clipped: part of it out of view, so it may be larger}]",
        ),
        InputSpec("partner_in_view", "bool", "another robot's colour is in the forward camera's image"),
        InputSpec("hand_give_left", "float", "metres: how far the load pulls the left hand off its posture"),
        InputSpec(
            "hand_give_right", "float", "metres: how far the load pulls the right hand off its posture"
        ),
        InputSpec("holding", "bool", "the hands carry a load"),
        InputSpec(
            "pose",
            "dict",
            "odometry, {x: metres, y: metres, yaw: degrees, left positive}: in the robot's own start "
            "frame (full body), or in the room's frame from the start pose the scenario tells it, "
            "corrected against the room's walls by the robot's laser scans (light body)",
        ),
        InputSpec(
            "radio_delay",
            "float",
            "seconds the latest message or barrier notice this robot heard took on the radio (its "
            "sender's time stamp to its arrival, by the robots' synchronised clocks); 0 before any",
        ),
        InputSpec("battery", "float", "the battery's charge, 0 (empty: the robot fails) to 1 (full)"),
        InputSpec(
            "tasks",
            "list",
            "the tasks the team is given, in scenario order, tables then targets: [{id, kind: "
            "table|target, x, y: metres in the room's frame (a table's start centre), difficulty: "
            "0..1, priority: 1 first; a table also has yaw: degrees of its long side, length, "
            "width: metres}]",
        ),
        InputSpec(
            "start",
            "dict",
            "where the robot was told it was placed, {x, y: metres, yaw: degrees} in the room's frame: "
            "the scenario's start pose as written, not the jittered truth (in.pose is odometry from there)",
        ),
        InputSpec("room", "dict", "the room the team is told it works in: {width, depth: metres}, centre 0"),
    )
}
