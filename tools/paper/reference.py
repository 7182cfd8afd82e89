"""The paper's published numbers (Figure 10), to print beside ours."""

from __future__ import annotations

BEHAVIOURS = (
    "look_for_table", "elect_leader", "leader", "wait_until_clear_way", "go_to_table",
    "position_to_centre_of_table_side", "go_to_the_lifting_point", "assistant", "look_for_leader",
    "clear_way", "wait_until_leader_at_centre_of_table", "go_to_opposite_side_of_table", "move_table",
    "recentre_to_middle_of_table", "align_to_middle_of_table", "synchronised_lift_table",
    "small_step_sideways", "land_table",
)  # fmt: skip

SCENARIOS = (
    ("opposite_long_side", "Robots standing opposite to each other, long side"),
    ("ahead_behind", "Robots starting ahead and behind each other"),
    ("facing_away", "Robots starting facing away from the table"),
    ("facing_table", "Robots starting facing the table"),
    ("same_side", "Robots starting on the same side"),
    ("opposite_short_side", "Robots starting opposite to each other, short side"),
)

# Seconds per behaviour, in BEHAVIOURS order, then the paper's total (s) and its minutes.
PAPER: dict[str, tuple[tuple[int, ...], int, float]] = {
    "opposite_long_side": ((6, 8, 572, 0, 25, 133, 414, 784, 1, 0, 572, 212, 233, 56, 112, 12, 40, 13), 1603, 26.7),
    "ahead_behind": ((6, 8, 728, 156, 25, 133, 414, 940, 1, 156, 572, 212, 233, 56, 112, 12, 40, 13), 1915, 31.9),
    "facing_away": ((112, 8, 600, 28, 25, 133, 414, 812, 1, 28, 572, 212, 233, 56, 112, 12, 40, 13), 1765, 29.4),
    "facing_table": ((0, 8, 572, 0, 25, 133, 414, 784, 1, 0, 572, 212, 233, 56, 112, 12, 40, 13), 1597, 26.6),
    "same_side": ((6, 8, 728, 156, 25, 133, 414, 940, 1, 156, 572, 212, 233, 56, 112, 12, 40, 13), 1915, 31.9),
    "opposite_short_side": ((6, 8, 572, 0, 25, 133, 414, 784, 1, 0, 572, 212, 233, 56, 112, 12, 40, 13), 1603, 26.7),
}  # fmt: skip
PAPER_MEAN_MINUTES = 28.9
PAPER_LIMIT_SECONDS = 35 * 60
PAPER_NO_WAIT_MINUTES = 12.0
PAPER_NO_WAIT_COLLISIONS = 0.30
