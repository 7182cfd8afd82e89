"""Primitives of the TARARC team (machines/tararc*.yaml): the radio's exchanges, the plan, the history.

Pure of any world: they hear and say over the radio and compute with `hfsm_behaviours.tararc`, so they
run in every world, `none` included. Moving to a place is the world's (`go_to`).
"""

from __future__ import annotations

from hfsm.primitive import Primitive
from hfsm_behaviours.teamwork.exchange import tararc_agreed, tararc_hold, tararc_merge
from hfsm_behaviours.teamwork.memory import tararc_recall, tararc_remember
from hfsm_behaviours.teamwork.plans import tararc_allocate, tararc_help
from hfsm_behaviours.teamwork.radio import partner_silent, tararc_watch
from hfsm_behaviours.teamwork.recovery import (
    room_channel,
    room_job,
    room_lend,
    room_replace,
    room_role,
    room_slides,
    room_stranded,
    room_tried,
)
from hfsm_behaviours.teamwork.room import (
    room_allocate,
    room_hear,
    room_locate,
    room_news,
    room_relocalise,
    room_settle,
)
from hfsm_behaviours.teamwork.walk import room_aside, room_give_way, room_route

PRIMITIVES: tuple[Primitive, ...] = (
    tararc_recall,
    tararc_hold,
    tararc_merge,
    tararc_agreed,
    tararc_allocate,
    tararc_watch,
    tararc_help,
    tararc_remember,
    partner_silent,
    room_allocate,
    room_slides,
    room_replace,
    room_tried,
    room_lend,
    room_stranded,
    room_role,
    room_channel,
    room_job,
    room_locate,
    room_relocalise,
    room_news,
    room_hear,
    room_settle,
    room_route,
    room_aside,
    room_give_way,
)
