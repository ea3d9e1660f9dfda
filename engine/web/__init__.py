"""The head in a web page: ``artificial-person web-export`` writes a folder that plays it offline
(three.js vendored, the model as a compact glTF, the animation as JSON, the audio) —
docs/web-export.md.

Nothing here imports a browser or a GUI; the player itself is ``engine/web/player/player.js``.
"""

from engine.web.site import project, site_camera, write_site, write_speech_site, write_tracks_site

__all__ = ["project", "site_camera", "write_site", "write_speech_site", "write_tracks_site"]
