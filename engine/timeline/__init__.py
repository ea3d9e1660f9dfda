"""The timeline (§2.3): low-level command keys → the value of every parameter at any time.

>>> from engine.timeline import Timeline
"""

from engine.timeline.timeline import Timeline

__all__ = ["Timeline"]
