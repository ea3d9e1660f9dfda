"""The task layouts, as data: where each dock goes for Model, Painting, Motion capture, Animation/Speech, Library.

A :class:`TaskLayout` names which docks share the left column, the right
column and the bottom row (each a list of :class:`Stack` s, a stack being
docks tabbed together), how much of the window each takes, and which docks
are open. Every dock has a place in every layout, open or not, so a dock
opened later (Ctrl+L, Ctrl+G, the Motion capture menu) appears where it fits
that task. :class:`workbench.window.layouts.LayoutManager` builds them.
"""

from __future__ import annotations

from dataclasses import dataclass

PARAMETERS, TOOL_OPTIONS, TREE = "dock:parameters", "dock:tool-options", "dock:parameter-tree"
SCRIPT, GALLERY, TIMELINE = "dock:script", "dock:expression-gallery", "dock:timeline"
LIBRARY_EDITOR, MOCAP_PLOT, MOCAP_PCA = "dock:library-editor", "dock:mocap-plot", "dock:mocap-pca"
IDENTITY = "dock:identity"     # opened from View → Identity, a tab beside the sliders


@dataclass(frozen=True)
class Stack:
    """Docks tabbed together (the first open one in front), taking ``share`` of their column's length.

    On a short screen (docks and viewport less than ``tabbed_below`` px high) the stack joins the one
    before it as more tabs, instead of squeezing both.
    """

    docks: tuple[str, ...]
    share: float = 1.0
    tabbed_below: int = 0


@dataclass(frozen=True)
class TaskLayout:
    """Where every dock goes for one task; widths and heights are shares of the window."""

    id: str
    title: str
    tip: str
    shown: frozenset[str]
    left: tuple[Stack, ...]
    right: tuple[Stack, ...]
    bottom: tuple[Stack, ...]
    left_width: float = 0.24
    right_width: float = 0.30
    bottom_height: float = 0.30
    bottom_spans_window: bool = False   # the bottom row runs under the side columns too

    @property
    def docks(self) -> list[str]:
        return [name for area in (self.left, self.right, self.bottom) for stack in area for name in stack.docks]


LAYOUTS: tuple[TaskLayout, ...] = (
    TaskLayout("model", "Model", "The parameter tree, its properties, the sliders and the timeline",
               frozenset({TREE, SCRIPT, PARAMETERS, TOOL_OPTIONS, TIMELINE}),
               left=(Stack((TREE,), 0.5), Stack((SCRIPT, GALLERY), 0.5)),
               right=(Stack((PARAMETERS, IDENTITY), 0.56), Stack((TOOL_OPTIONS, MOCAP_PCA), 0.44)),
               bottom=(Stack((TIMELINE, LIBRARY_EDITOR, MOCAP_PLOT)),), left_width=0.25, right_width=0.31),
    TaskLayout("painting", "Painting", "A large face to paint on, the brush's options and the parameter tree",
               frozenset({TREE, TOOL_OPTIONS, PARAMETERS}),
               left=(Stack((TREE,), 0.6), Stack((SCRIPT, GALLERY), 0.4)),
               right=(Stack((TOOL_OPTIONS, MOCAP_PCA), 0.7), Stack((PARAMETERS, IDENTITY), 0.3)),
               bottom=(Stack((TIMELINE, LIBRARY_EDITOR, MOCAP_PLOT)),), left_width=0.25, right_width=0.31),
    TaskLayout("mocap", "Motion capture", "The marker coordinate plot under the face, the multistage PCA wizard "
               "beside it, the timeline to play the recording",
               frozenset({MOCAP_PLOT, MOCAP_PCA, PARAMETERS, TIMELINE}),
               left=(Stack((TREE,)), Stack((SCRIPT, GALLERY))),
               right=(Stack((MOCAP_PCA, PARAMETERS, TOOL_OPTIONS, IDENTITY)),),
               bottom=(Stack((MOCAP_PLOT, LIBRARY_EDITOR), 0.7), Stack((TIMELINE,), 0.3)),
               right_width=0.42, bottom_height=0.37, bottom_spans_window=True),
    TaskLayout("animation", "Animation/Speech", "The script panel and the expression gallery, the timeline, "
               "the sliders", frozenset({SCRIPT, GALLERY, TIMELINE, PARAMETERS}),
               left=(Stack((SCRIPT,), 0.4), Stack((GALLERY, TREE), 0.6, tabbed_below=820)),
               right=(Stack((PARAMETERS, IDENTITY, TOOL_OPTIONS, MOCAP_PCA)),),
               bottom=(Stack((TIMELINE, MOCAP_PLOT, LIBRARY_EDITOR)),),
               left_width=0.3, right_width=0.25, bottom_height=0.3),
    TaskLayout("library", "Library", "The library editor across the window, the expression gallery, the sliders",
               frozenset({LIBRARY_EDITOR, TIMELINE, GALLERY, PARAMETERS}),
               left=(Stack((GALLERY, TREE, SCRIPT)),),
               right=(Stack((PARAMETERS, IDENTITY, TOOL_OPTIONS, MOCAP_PCA)),),
               bottom=(Stack((LIBRARY_EDITOR, TIMELINE, MOCAP_PLOT)),),
               left_width=0.3, right_width=0.25, bottom_height=0.56, bottom_spans_window=True),
)
BY_ID = {layout.id: layout for layout in LAYOUTS}
DEFAULT_LAYOUT = "model"
