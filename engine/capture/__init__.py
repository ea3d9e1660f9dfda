"""Today's face-capture streams (ARKit / Live Link Face, OpenFace 2, MediaPipe) driving the head.

See docs/capture-streams.md.
"""
