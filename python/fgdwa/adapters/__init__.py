"""fgdwa inside other programs' loops: the ROS 1 node's planner replayed on a
bag (``replay``, ``fgdwa replay BAG``), and fgdwa as an IR-SIM behavior
(``irsim``, with the worlds in ``irsim_worlds/``). ``fgdwa.adapters.irsim`` is
imported on its own: it needs IR-SIM (``pip install 'fgdwa[irsim]'``) and
registers the behavior when imported.
"""

from fgdwa.adapters.replay import Recording, ReplayCycle, navigator_from_event, read_recording, replay

__all__ = ["Recording", "ReplayCycle", "navigator_from_event", "read_recording", "replay"]
