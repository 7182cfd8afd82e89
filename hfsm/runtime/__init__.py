"""The interpreter: compiled machines, agents and their frames, activities, and the tick loop."""
