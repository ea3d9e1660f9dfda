"""The Identity dock: who the head is — sex, age, ancestry, build and about 180 face modifiers — as sliders.

:func:`install` adds the dock ``dock:identity`` (View → Identity, Ctrl+Shift+I;
hidden until opened, tabbed with the Parameters dock) as
``window.identity_panel``. The panel shows the identity of the document's
model (:attr:`engine.Model.identity`; the default head's when it has none):
the macro parameters first, then the face modifiers in folding groups (head,
forehead, eyebrows, eyes, nose, mouth, cheek, chin, ears, neck), a search
field over every name, a reset per row, per group and for all. Dragging a
slider reshapes the face in the viewport live; releasing it makes the head
with the rig carried over (off the GUI thread) as one undo step
(:mod:`workbench.identity_panel.heads`). *Save identity as…* writes the model
with its identity. The rows are built the first time the dock is shown, so
a workbench that never opens it never loads the identity data.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QSize, Qt
from PySide6.QtGui import QFont, QFontMetrics, QShowEvent
from PySide6.QtWidgets import (
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QMessageBox,
    QPushButton,
    QScrollArea,
    QStyle,
    QVBoxLayout,
    QWidget,
)

from engine.errors import UserError

from ..icons import icon
from .heads import IdentityHeads, identity_of
from .rows import IdentityGroup, IdentitySlider

if TYPE_CHECKING:
    from engine.identity import Identity

    from ..window.main_window import MainWindow

DOCK_NAME = "dock:identity"
USEFUL_HEIGHT = 520
NOTE_LINES = 2       # the note under the rows keeps room for this many lines, so the rows never move
NOTE_STYLE = {"info": "color: palette(dark)", "busy": "color: #2f5f8f", "error": "color: #a02020"}


class IdentityPanel(QWidget):
    """Sliders over the identity of ``window.document``'s model; see the module's description."""

    def __init__(self, window: MainWindow, parent: QWidget | None = None):
        super().__init__(parent)
        self.window_ = window
        self.document = window.document
        self.heads = IdentityHeads(window.document, window.viewport, self)
        self.heads.ask_discard = self.ask_discard
        self.groups: dict[str, IdentityGroup] = {}
        self.rows: dict[str, IdentitySlider] = {}
        self.values: dict[str, float] = {}       # what the rows show: the identity being made or the document's

        self.note = QLabel()
        self.note.setWordWrap(True)
        self.note.setObjectName("identity-note")
        self.note.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        self.note.setMinimumHeight(NOTE_LINES * self.note.fontMetrics().lineSpacing())
        self.search = QLineEdit()
        self.search.setPlaceholderText("Find a parameter (nose, lip, .left …)")
        self.search.setClearButtonEnabled(True)
        self.search.textChanged.connect(self.filter)
        self.scroll = QScrollArea()
        self.scroll.setWidgetResizable(True)
        self.scroll.setFrameShape(QScrollArea.Shape.NoFrame)
        self.reset_all_button = QPushButton(icon("reset"), "Reset all")
        self.reset_all_button.setToolTip("Make the default head's identity again (one undo step)")
        self.reset_all_button.clicked.connect(self.reset_all)
        self.save_button = QPushButton(icon("save-as"), "Save identity as…")
        self.save_button.setToolTip("Write this head with its identity to a new .xml + .h5 pair")
        self.save_button.clicked.connect(self.save_identity_as)
        buttons = QHBoxLayout()
        buttons.addWidget(self.reset_all_button)
        buttons.addStretch(1)
        buttons.addWidget(self.save_button)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        # The note is under the rows, not above them: when it changes (a value changed, "Making the head…")
        # the rows stay where they are, and the click the user is about to make lands where it was aimed.
        layout.addWidget(self.search)
        layout.addWidget(self.scroll, 1)
        layout.addWidget(self.note)
        layout.addLayout(buttons)

        self.heads.busy_changed.connect(self._on_busy)
        self.heads.failed.connect(self._on_failed)
        self.heads.settled.connect(self.sync)
        self.document.model_replaced.connect(self._on_model_replaced)

    # -- building (on first show) ---------------------------------------------------------------
    @property
    def built(self) -> bool:
        return bool(self.rows)

    def ensure_built(self) -> None:
        """Make the rows (the identity data are read now, the first time)."""
        if self.built:
            return
        from engine.identity import identity_parameters

        by_group: dict[str, list] = {}
        for parameter in identity_parameters():
            by_group.setdefault(parameter.group, []).append(parameter)
        content = QWidget()
        column = QVBoxLayout(content)
        column.setContentsMargins(0, 0, 0, 0)
        column.setSpacing(2)
        for group, parameters in by_group.items():
            box = IdentityGroup(group, parameters)
            box.moved.connect(self.preview)
            box.committed.connect(self.commit)
            box.reset_requested.connect(self.reset_group)
            self.groups[group] = box
            self.rows.update(box.rows)
            column.addWidget(box)
        column.addStretch(1)
        bold = QFont(next(iter(self.rows.values())).label.font())
        bold.setBold(True)          # a changed value's label is bold: its column is as wide as that already
        metrics = QFontMetrics(bold)
        label_width = max(max(row.label.sizeHint().width(), metrics.horizontalAdvance(row.label.text()) + 4)
                          for row in self.rows.values())
        for box in self.groups.values():
            box.set_label_width(label_width)
        if "macro" in self.groups:
            self.groups["macro"].set_expanded(True)
        self.scroll.setWidget(content)
        self.sync()

    def showEvent(self, event: QShowEvent) -> None:
        super().showEvent(event)
        self.ensure_built()

    def sizeHint(self) -> QSize:
        if not self.built:
            return QSize(380, USEFUL_HEIGHT)
        content = self.scroll.widget()
        scroll_bar = self.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent)
        return QSize(content.sizeHint().width() + scroll_bar + 12, USEFUL_HEIGHT)

    # -- showing the document's identity --------------------------------------------------------
    def sync(self) -> None:
        """Show the identity of the document's model (unless a head is being made: then at its end)."""
        if not self.built or self.heads.busy:
            return
        model = self.document.model
        why_not = self.heads.unavailable()
        try:
            identity = identity_of(model)
        except UserError as error:
            identity, why_not = None, f"This model's identity cannot be shown: {error}"
        self.values = {name: identity.value(name) if identity is not None else row.parameter.default
                       for name, row in self.rows.items()}
        for box in self.groups.values():
            box.show_values(self.values)
            box.setEnabled(why_not is None)
        self.reset_all_button.setEnabled(why_not is None and identity is not None and bool(identity.values))
        self.save_button.setEnabled(why_not is None)
        if why_not is not None:
            self._say(why_not, "error")
        elif identity is not None and identity.values:
            shares = ", ".join(f"{100 * share:.0f}% {race}" for race, share in identity.ancestry().items())
            count = len(identity.values)
            differ = "1 value differs" if count == 1 else f"{count} values differ"
            self._say(f"{differ} from the default head. Ancestry, normalised: {shares}.", "info")
        else:
            self._say("The default head's identity. Drag a slider to reshape the face.", "info")

    def filter(self, text: str) -> None:
        """Show only the rows whose names hold ``text``; groups with a match open."""
        for box in self.groups.values():
            shown = box.filter(text)
            if text.strip():
                box.set_expanded(shown > 0)

    # -- what the user does -------------------------------------------------------------------------
    def preview(self, name: str, value: float) -> None:
        """A row moves: show that face live (nothing is made or undone yet)."""
        identity = self._identity_with({name: value})
        if identity is not None:
            self.heads.preview(identity)

    def commit(self, name: str, value: float) -> None:
        """A row's value is meant: make the head, one undo step."""
        old = self.values.get(name, value)
        if value == old:
            return
        identity = self._identity_with({name: value})
        if identity is None:
            self.rows[name].show_value(old)
            self.heads.end_preview()
            return
        self.values[name] = value
        self.rows[name].group.update_header()
        self.heads.request(identity, f"Identity: {name} {old:g} → {value:g}")

    def reset_group(self, group: str) -> None:
        box = self.groups[group]
        changed = box.changed_names()
        if not changed:
            return
        defaults = {name: box.rows[name].parameter.default for name in changed}
        identity = self._identity_with(defaults)
        if identity is None:
            return
        self.values.update(defaults)
        box.show_values(self.values)
        self.heads.preview(identity)
        self.heads.request(identity, f"Identity: reset {box.title}")

    def reset_all(self) -> None:
        from engine.identity import Identity

        self.values = {name: row.parameter.default for name, row in self.rows.items()}
        for box in self.groups.values():
            box.show_values(self.values)
        self.heads.preview(Identity())
        self.heads.request(Identity(), "Identity: reset all")

    def save_identity_as(self) -> bool:
        """Ask for a file and write the head with its identity (File → Save model as…, named after the identity)."""
        return self.window_.files.save_identity_as_dialog()

    def ask_discard(self, reason: str) -> bool:
        """Whether to make the new identity although ``reason`` says what it loses (tests replace this)."""
        answer = QMessageBox.question(self, "Change the identity?", f"{reason}\n\nChange the identity anyway? "
                                      "(Undo brings the edited head back.)",
                                      QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.Cancel,
                                      QMessageBox.StandardButton.Cancel)
        return answer == QMessageBox.StandardButton.Yes

    # -- helpers -------------------------------------------------------------------------------------
    def _identity_with(self, changes: dict[str, float]) -> Identity | None:
        """The identity shown with ``changes``; ``None`` (and the reason shown) if it is not one."""
        from engine.identity import Identity

        values = {**self.values, **changes}
        try:
            return Identity({name: v for name, v in values.items() if v != self.rows[name].parameter.default})
        except UserError as error:
            self._say(str(error), "error")
            return None

    def _on_model_replaced(self, _model) -> None:
        self.sync()

    def _on_busy(self, busy: bool) -> None:
        if busy:
            self._say("Making the head (carrying the rig over)…", "busy")

    def _on_failed(self, message: str) -> None:
        self.sync()
        self._say(f"No new head: {message}", "error")

    def _say(self, text: str, kind: str) -> None:
        self.note.setText(text)
        self.note.setStyleSheet(NOTE_STYLE[kind])


def install(window: MainWindow) -> None:
    """Add the Identity dock (hidden) and its View-menu entry to ``window``."""
    panel = IdentityPanel(window)
    dock = QDockWidget("Identity", window)
    dock.setObjectName(DOCK_NAME)
    dock.setWidget(panel)
    window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, dock)   # the task layouts give it its place
    dock.hide()
    dock.useful_size = panel.sizeHint
    window.identity_panel = panel
    window.identity_dock = dock
    toggle = dock.toggleViewAction()
    toggle.setIcon(icon("identity"))
    toggle.setText("&Identity")
    toggle.setShortcut("Ctrl+Shift+I")
    toggle.setToolTip("Who the head is: sex, age, ancestry, build and the face's shape, as sliders")
    toggle.setStatusTip(toggle.toolTip())
    window.menus["&View"].addAction(toggle)
    window.actions_by_id["view.identity"] = toggle
