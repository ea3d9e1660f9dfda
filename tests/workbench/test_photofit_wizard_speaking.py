"""The photo-fit wizard's Stop inside a step, and its result page speaking (issue 19's workbench leftovers).

Real window, real fit on the wizard's worker thread, real Festival, real
pyvista rendering under Xvfb. Stop is pressed while the fit is in its
slowest step (the texture) on two 2-megapixel photographs; the fit's own
record (:class:`~workbench.photofit_wizard.fit.FitTrace`) shows where it
stopped: inside that step, at the first question after Stop, no later step
begun. No assertion reads a clock.
"""

from __future__ import annotations

import os

import numpy as np
import pytest
from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import QWizard

from engine.speech.festival import SynthesisCancelled
from tests.engine.test_long_speech import LONG_TEXT, alive, festival_children, wait_for
from tests.workbench.test_photofit_wizard import (  # noqa: F401  (fixtures)
    FIT_TIMEOUT_MS,
    head_window,
    open_wizard,
    photographs,
    wait_for_jobs,
    write_photographs,
)
from workbench.photofit_wizard.fit import FitStopped

TWO_MEGAPIXELS = (1224, 1632)            # width, height: 2.0 million pixels
QUESTIONS_BEFORE_STOP = 10               # the texture step asks hundreds of times on these photographs


@pytest.fixture(scope="module")
def large_photographs(tmp_path_factory, head):
    """Front and side PNGs of the default head at 2 megapixels, and POINTS.json with the true pixels."""
    folder = tmp_path_factory.mktemp("large")
    write_photographs(folder, head, TWO_MEGAPIXELS)
    return folder


def test_stop_ends_the_fit_inside_its_slowest_step(head_window, large_photographs, qtbot):  # noqa: F811
    document = head_window.document
    before, steps_before = document.model, document.undo_stack.count()
    wizard = open_wizard(head_window, qtbot)
    assert wizard.photos_page.choose("front", large_photographs / "front.png")
    assert wizard.photos_page.choose("side", large_photographs / "side.png")
    wizard.next()
    assert wizard.landmark_page.load(large_photographs / "points.json")
    wizard.next()
    page = wizard.fit_page
    job, trace = page.job, page.trace
    ended: list[BaseException | None] = []
    job.ended.connect(lambda: ended.append(job.error))
    qtbot.waitUntil(lambda: trace.steps[-1:] == ["texture"] and trace.questions["texture"] >= QUESTIONS_BEFORE_STOP,
                    timeout=FIT_TIMEOUT_MS)
    qtbot.mouseClick(page.stop_button, Qt.MouseButton.LeftButton)       # Stop in the middle of the texture
    assert page.status.text() == "Stopped: nothing was kept." and not page.running
    qtbot.waitUntil(lambda: bool(ended), timeout=FIT_TIMEOUT_MS)
    assert isinstance(ended[0], FitStopped)
    assert trace.steps[-1] == "texture"              # no later step began ...
    assert trace.asked_after_stop == 1               # ... and the texture step ended at its first question
    assert wizard.session.fit is None and not page.isComplete()
    assert document.model is before and document.undo_stack.count() == steps_before
    wizard.reject()


def mouth_gap(vertices, head) -> float:
    """mm between the inner lips' midpoints (MPEG-4 2.2 and 2.3)."""
    return float(np.linalg.norm(vertices[head.landmarks["2.2"]] - vertices[head.landmarks["2.3"]]))


def open_vowel_ms(speech) -> float:
    """The middle of the longest 'a' the utterance says, ms."""
    vowel = max((p for p in speech.utterance.phones if p.label.startswith("a")), key=lambda p: p.end_ms - p.start_ms)
    return (vowel.start_ms + vowel.end_ms) / 2


def test_the_result_page_speaks_and_cancel_stops_festival(head_window, photographs, qtbot):  # noqa: F811
    window = head_window
    document = window.document
    before, values_before = document.model, dict(document.values)
    wizard = open_wizard(window, qtbot)
    assert wizard.photos_page.choose("front", photographs / "front.png")
    wizard.next()
    assert wizard.landmark_page.load(photographs / "front-points.json")
    wizard.next()
    qtbot.waitUntil(wizard.fit_page.isComplete, timeout=FIT_TIMEOUT_MS)
    head = wizard.session.fit.head
    wizard.next()
    page = wizard.result_page
    assert page.viewport.isVisible() and page.viewport.textures_shown()
    assert page.document.model is head and page.document is not document

    # Say: Festival on a worker thread; the click returns while it runs
    qtbot.mouseClick(page.say_button, Qt.MouseButton.LeftButton)
    job = page.job
    assert job is not None and job.isRunning()
    qtbot.waitUntil(lambda: page.player.is_playing, timeout=FIT_TIMEOUT_MS)
    assert page.speech.timeline.model is head and page.player.duration > 0.5
    assert page.status.text().startswith("Saying: Pappa ampui pallon")
    # the page's head moves, the window's document does not
    page.player.pause()
    rest = mouth_gap(page.document.model.deform(page.document.model.default_values()), head)
    page.playhead.set_time(open_vowel_ms(page.speech) / 1000)
    assert mouth_gap(page.document.vertices(), head) > rest + 2.0                  # mm: the mouth is open
    assert np.allclose(page.viewport.displayed_points()[head.landmarks["2.3"]],
                       page.document.vertices()[head.landmarks["2.3"]])            # and the view shows it
    assert document.model is before and document.values == values_before

    # a sentence Festival works on for minutes: the page keeps answering, Cancel ends Festival
    page.sentence.setText(LONG_TEXT)
    page.say()
    children = wait_for(lambda: festival_children(os.getpid()))
    assert children, "Say never started Festival"
    job = page.job
    turned: list[bool] = []
    QTimer.singleShot(0, lambda: turned.append(True))
    qtbot.waitUntil(lambda: bool(turned))                                          # the event loop turns
    assert job.isRunning() and page.synthesizing
    wizard.button(QWizard.WizardButton.CancelButton).click()
    assert not wizard.isVisible()
    wait_for_jobs(qtbot)
    assert isinstance(job.error, SynthesisCancelled)
    assert not any(alive(pid) for pid in children)
    assert document.model is before and not document.is_modified
