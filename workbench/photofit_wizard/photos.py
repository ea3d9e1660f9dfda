"""The wizard's first page: a front photograph (required) and a side one (optional), JPEG or PNG.

Each is read by :func:`engine.photofit.read_photo` (EXIF orientation
applied, as every viewer shows it); a file it refuses opens a dialog naming
the file and leaves the choice as it was.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QFileDialog,
    QGridLayout,
    QLabel,
    QMessageBox,
    QPushButton,
    QWizardPage,
)

from engine.photofit import PhotoFitError, read_photo

from .canvas import pixmap_of
from .session import TITLE, VIEWS, PhotoFitSession

THUMBNAIL = 260
FILTER = "Photographs (*.jpg *.jpeg *.png *.JPG *.JPEG *.PNG);;All files (*)"
CAPTIONS = {"front": "Front photograph (required): the face straight on",
            "side": "Side photograph (optional): the subject's left side, in profile"}


class PhotosPage(QWizardPage):
    photo_changed = Signal(str)

    def __init__(self, session: PhotoFitSession):
        super().__init__()
        self.session = session
        self.setTitle("Photographs")
        self.setSubTitle("Choose a JPEG or PNG photograph of the face from the front and, if you have one, "
                         "from the left side. Even light and a plain background fit best.")
        grid = QGridLayout(self)
        self.names: dict[str, QLabel] = {}
        self.thumbnails: dict[str, QLabel] = {}
        self.clear_buttons: dict[str, QPushButton] = {}
        for column, view in enumerate(VIEWS):
            grid.addWidget(QLabel(CAPTIONS[view]), 0, column)
            thumbnail = self.thumbnails[view] = QLabel("no photograph")
            thumbnail.setAlignment(Qt.AlignmentFlag.AlignCenter)
            thumbnail.setFixedSize(THUMBNAIL, THUMBNAIL)
            thumbnail.setStyleSheet("QLabel { background: #30343a; color: #aaa; }")
            grid.addWidget(thumbnail, 1, column)
            name = self.names[view] = QLabel("")
            name.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
            grid.addWidget(name, 2, column)
            browse = QPushButton("Choose…")
            browse.setObjectName(f"photofit.choose_{view}")
            browse.clicked.connect(lambda _=False, view=view: self.choose_dialog(view))
            grid.addWidget(browse, 3, column)
            if view != "front":
                clear = self.clear_buttons[view] = QPushButton("No side photograph")
                clear.clicked.connect(lambda _=False, view=view: self.forget(view))
                clear.setEnabled(False)
                grid.addWidget(clear, 4, column)
        self.find_box = QCheckBox("Find the face's points by themselves (dlib's face detector and 68 points)")
        self.find_box.setToolTip("Off: the points start at a first guess, the head centred on the photograph. "
                                 "The side photograph's points always start so: dlib finds no profile.")
        self.find_box.setChecked(session.find_points)
        self.find_box.toggled.connect(self._find_toggled)
        grid.addWidget(self.find_box, 5, 0, 1, len(VIEWS))
        grid.setRowStretch(6, 1)

    def _find_toggled(self, on: bool) -> None:
        self.session.find_points = on             # the landmark page places the front's points again

    def choose_dialog(self, view: str) -> None:
        folder = str(self.session.paths[view].parent) if view in self.session.paths else ""
        path, _ = QFileDialog.getOpenFileName(self, f"{view.capitalize()} photograph", folder, FILTER)
        if path:
            self.choose(view, path)

    def choose(self, view: str, path: str | Path) -> bool:
        """Read ``path`` as the ``view`` photograph; a dialog and ``False`` if it cannot be used."""
        try:
            photo = read_photo(path)
        except PhotoFitError as error:
            QMessageBox.critical(self, TITLE, f"{error}\n\nChoose a JPEG or PNG photograph.")
            return False
        self.session.photos[view] = photo
        self.session.paths[view] = Path(path)
        height, width = photo.shape[:2]
        self.names[view].setText(f"{Path(path).name}  ({width} × {height})")
        self.thumbnails[view].setPixmap(pixmap_of(photo).scaled(
            THUMBNAIL, THUMBNAIL, Qt.AspectRatioMode.KeepAspectRatio, Qt.TransformationMode.SmoothTransformation))
        if view in self.clear_buttons:
            self.clear_buttons[view].setEnabled(True)
        self.photo_changed.emit(view)
        self.completeChanged.emit()
        return True

    def forget(self, view: str) -> None:
        self.session.photos.pop(view, None)
        self.session.paths.pop(view, None)
        self.names[view].setText("")
        self.thumbnails[view].clear()
        self.thumbnails[view].setText("no photograph")
        if view in self.clear_buttons:
            self.clear_buttons[view].setEnabled(False)
        self.photo_changed.emit(view)
        self.completeChanged.emit()

    def isComplete(self) -> bool:
        return "front" in self.session.photos
