"""The review dock alone: buttons and shortcuts emit its signals, clicks map to image pixels, the picker filters."""

import pytest
from qgis.PyQt.QtCore import QPoint, Qt
from qgis.PyQt.QtGui import QColor, QImage
from qgis.PyQt.QtTest import QTest
from qgis.PyQt.QtWidgets import QApplication, QToolButton


@pytest.fixture
def ui(sign_mapper):
    from sign_mapper.ui import image_view, review_dock, review_item, template_picker

    return review_dock, review_item, template_picker, image_view


@pytest.fixture
def dock(ui):
    review_dock, review_item, template_picker, _ = ui
    widget = review_dock.ReviewDock()
    widget.resize(420, 760)
    widget.set_template_choices([
        template_picker.TemplateChoice("2.30-50", "Höchstgeschwindigkeit 50", "red", "circle"),
        template_picker.TemplateChoice("2.30-80", "Höchstgeschwindigkeit 80", "red", "circle"),
        template_picker.TemplateChoice("1.01", "Rechtskurve", "red", "triangle"),
        template_picker.TemplateChoice("2.37", "Gebotene Fahrtrichtung rechts", "blue", "circle"),
    ])
    image = QImage(200, 100, QImage.Format_RGB32)
    image.fill(QColor(90, 90, 90))
    widget.set_navigation_enabled(True, can_add=True)  # the controller's part: a layer with its drive
    widget.show_item(review_item.ReviewItem(
        "detections", 3, "detections · feature 3", template_id="2.30-50", name="Höchstgeschwindigkeit 50",
        colour="red", shape="circle", format="normal", size_m=(0.6, 0.6), status="review", pair_id="000004",
        time=0.8, bbox=(80, 30, 40, 40), centroid=(99.5, 49.5), crop=(40, 0, 120, 100), image=image,
        position=(2600010.0, 1200004.0, 403.1),
    ))
    widget.show()
    QApplication.setActiveWindow(widget)
    QApplication.processEvents()
    yield widget
    widget.close()
    widget.deleteLater()


class Recorder:
    def __init__(self, dock):
        self.calls = []
        for name in ("acceptRequested", "rejectRequested", "nextRequested", "previousRequested",
                     "nextReviewRequested", "zoomRequested", "undoRequested"):
            getattr(dock, name).connect(lambda name=name: self.calls.append((name,)))
        dock.reclassifyRequested.connect(lambda tid: self.calls.append(("reclassifyRequested", tid)))
        dock.addSignClicked.connect(lambda pair, u, v: self.calls.append(("addSignClicked", pair, u, v)))


BUTTON_SIGNALS = [
    ("accept", "acceptRequested"), ("reject", "rejectRequested"), ("next", "nextRequested"),
    ("previous", "previousRequested"), ("next_review", "nextReviewRequested"), ("zoom", "zoomRequested"),
]


@pytest.mark.parametrize("button, signal", BUTTON_SIGNALS)
def test_buttons_emit_their_signal(dock, button, signal):
    rec = Recorder(dock)
    QTest.mouseClick(dock.buttons[button], Qt.LeftButton)
    assert rec.calls == [(signal,)]


@pytest.mark.parametrize("key, signal", [
    (Qt.Key_A, "acceptRequested"), (Qt.Key_R, "rejectRequested"), (Qt.Key_N, "nextRequested"),
    (Qt.Key_P, "previousRequested"), (Qt.Key_Space, "nextReviewRequested"), (Qt.Key_Z, "zoomRequested"),
])
def test_shortcuts_emit_their_signal(dock, key, signal):
    rec = Recorder(dock)
    dock.image_view.setFocus()
    QTest.keyClick(dock.image_view, key)
    assert rec.calls == [(signal,)]


def test_undo_button_and_shortcut_only_when_enabled(dock):
    rec = Recorder(dock)
    dock.image_view.setFocus()
    QTest.keyClick(dock.image_view, Qt.Key_U)
    assert rec.calls == []
    dock.set_undo_enabled(True, "accept feature 3")
    QTest.keyClick(dock.image_view, Qt.Key_U)
    QTest.mouseClick(dock.buttons["undo"], Qt.LeftButton)
    assert rec.calls == [("undoRequested",), ("undoRequested",)]


def test_decisions_are_disabled_without_an_item(dock):
    rec = Recorder(dock)
    dock.show_empty("nothing selected")
    QTest.mouseClick(dock.buttons["accept"], Qt.LeftButton)
    dock.image_view.setFocus()
    QTest.keyClick(dock.image_view, Qt.Key_R)
    assert rec.calls == []


def test_typing_in_the_search_box_does_not_trigger_shortcuts(dock):
    rec = Recorder(dock)
    dock.show_picker(True)
    QTest.keyClicks(dock.picker.search, "ra")
    assert rec.calls == []
    assert dock.picker.search.text() == "ra"


def test_picker_filters_by_colour_shape_and_text_and_emits_reclassify(dock):
    rec = Recorder(dock)
    QTest.keyClick(dock.image_view, Qt.Key_C)
    assert dock.picker_box.isVisible()
    # preset to the sign's colour and shape
    assert dock.picker.visible_ids() == ["2.30-50", "2.30-80"]
    dock.picker.set_filter("", "", "")
    assert len(dock.picker.visible_ids()) == 4
    dock.picker.set_filter("blue", "", "")
    assert dock.picker.visible_ids() == ["2.37"]
    dock.picker.set_filter("", "", "kurve")
    assert dock.picker.visible_ids() == ["1.01"]
    dock.picker.set_filter("red", "circle", "80")
    assert dock.picker.visible_ids() == ["2.30-80"]
    assert dock.picker.select("2.30-80")
    QTest.mouseClick(dock.picker.choose_button, Qt.LeftButton)
    assert rec.calls == [("reclassifyRequested", "2.30-80")]


def test_the_classifiers_next_choices_are_one_click_reclassifications(dock, ui):
    _, review_item, _, _ = ui
    rec = Recorder(dock)
    assert not dock.picker.suggested_ids()  # the fixture's item has none
    item = review_item.ReviewItem(
        "signs", 5, "signs · sign 5", template_id="2.30-50", colour="red", shape="circle", status="review",
        alternatives=[("2.30-80", 0.31), ("9.99", 0.2), ("1.01", 0.05)])
    dock.show_item(item)
    QTest.keyClick(dock.image_view, Qt.Key_C)
    assert dock.picker.suggested_ids() == ["2.30-80", "1.01"]  # 9.99 is no catalogue entry: not offered
    assert dock.picker.suggestions.isVisible()
    buttons = dock.picker.suggestions.findChildren(QToolButton)
    assert buttons[0].text() == "[1] 2.30-80\n0.31"  # its key, its id, its score
    QTest.mouseClick(buttons[1], Qt.LeftButton)
    assert rec.calls == [("reclassifyRequested", "1.01")]
    dock.show_empty("nothing selected")
    assert not dock.picker.suggested_ids()


def test_the_status_line_says_why_the_mapping_left_a_feature_for_review(dock, ui):
    _, review_item, _, _ = ui
    assert "<i>" not in dock.info["status"].text()  # the fixture's detection names no reason
    dock.show_item(review_item.ReviewItem("signs", 5, "signs · sign 5", template_id="2.30-50", status="review",
                                          review_reason="no view accepted: a zone panel's disc read alone"))
    assert dock.info["status"].text().endswith("· <i>no view accepted: a zone panel&#x27;s disc read alone</i>")


def test_the_picker_shows_every_id_whole(dock):
    dock.show_picker(True)
    dock.picker.set_filter("", "", "")
    QApplication.processEvents()
    grid = dock.picker.grid
    for i in range(grid.count()):
        item = grid.item(i)
        assert grid.visualItemRect(item).width() >= grid.fontMetrics().horizontalAdvance(item.text()), item.text()


def test_view_opens_on_the_crop_and_draws_the_bbox(dock):
    visible = dock.image_view.visible_image_rect()
    assert visible.contains(80, 30) and visible.contains(119, 69)
    assert visible.width() < 200 or visible.height() < 100  # zoomed in, not the whole image
    rect = dock.image_view.bbox_rect()
    assert (rect.x(), rect.y(), rect.width(), rect.height()) == (80, 30, 40, 40)


def test_click_emits_image_coordinates_only_when_adding_a_sign(dock):
    rec = Recorder(dock)
    view = dock.image_view
    target = view.image_to_view(100.0, 50.0)
    QTest.mouseClick(view.viewport(), Qt.LeftButton, Qt.NoModifier, target)
    assert rec.calls == []  # a plain click only pans
    QTest.keyClick(view, Qt.Key_M)
    assert dock.adding_sign()
    QTest.mouseClick(view.viewport(), Qt.LeftButton, Qt.NoModifier, target)
    assert len(rec.calls) == 1
    name, pair, u, v = rec.calls[0]
    assert (name, pair) == ("addSignClicked", "000004")
    scale = view.transform().m11()
    assert abs(u - 100.0) <= 1.0 / scale and abs(v - 50.0) <= 1.0 / scale
    assert not dock.adding_sign()  # one click adds one sign


def test_wheel_zooms(dock):
    from qgis.PyQt.QtCore import QPointF
    from qgis.PyQt.QtGui import QWheelEvent

    view = dock.image_view
    before = view.transform().m11()
    centre = QPointF(view.viewport().rect().center())
    event = QWheelEvent(centre, view.viewport().mapToGlobal(QPoint(0, 0)), QPoint(0, 0), QPoint(0, 240),
                        Qt.NoButton, Qt.NoModifier, Qt.NoScrollPhase, False)
    QApplication.sendEvent(view.viewport(), event)
    assert view.transform().m11() == pytest.approx(before * 1.25 ** 2)


def test_pair_box_and_observation_clicks_emit_requests(dock, ui):
    _, review_item, _, _ = ui
    pairs, observations = [], []
    dock.pairRequested.connect(pairs.append)
    dock.observationRequested.connect(observations.append)
    dock.set_pairs(["000003", "000004", "000005"])
    assert dock.pair_box.currentText() == "000004"  # the shown item's pair
    dock.pair_box.activated.emit(2)
    assert pairs == ["000005"]
    dock.set_observations([review_item.ObservationView("000003", "000003\n0.81"),
                           review_item.ObservationView("000004", "000004\n0.90")])
    assert dock.strip_box.isVisibleTo(dock) and dock.strip.count() == 2
    rect = dock.strip.visualItemRect(dock.strip.item(1))
    QTest.mouseClick(dock.strip.viewport(), Qt.LeftButton, Qt.NoModifier, rect.center())
    assert observations == [1]
    dock.set_observations(None)  # a detection has no strip
    assert not dock.strip_box.isVisibleTo(dock)


def test_keys_act_when_the_pointer_enters_the_dock_and_are_shown_on_the_buttons(dock):
    from qgis.PyQt.QtCore import QEvent
    from qgis.PyQt.QtWidgets import QLineEdit, QMainWindow, QPushButton, QVBoxLayout, QWidget

    rec = Recorder(dock)
    window = QMainWindow()  # as in QGIS: the dock beside the map canvas in one main window
    centre = QWidget()
    elsewhere, search = QPushButton("map canvas"), QLineEdit()
    column = QVBoxLayout(centre)
    column.addWidget(elsewhere)
    column.addWidget(search)
    window.setCentralWidget(centre)
    window.addDockWidget(Qt.RightDockWidgetArea, dock)
    window.show()
    QApplication.setActiveWindow(window)
    elsewhere.setFocus()
    QApplication.processEvents()
    assert QApplication.focusWidget() is elsewhere
    QApplication.sendEvent(dock, QEvent(QEvent.Enter))
    assert dock.isAncestorOf(QApplication.focusWidget())
    QTest.keyClick(QApplication.focusWidget(), Qt.Key_A)
    assert rec.calls == [("acceptRequested",)]
    assert dock.buttons["accept"].text() == "Accept [A]" and dock.buttons["next_review"].text().endswith("[Space]")
    search.setFocus()  # typing elsewhere keeps the focus there
    QApplication.processEvents()
    QApplication.sendEvent(dock, QEvent(QEvent.Enter))
    assert QApplication.focusWidget() is search
    window.removeDockWidget(dock)
    dock.setParent(None)  # the fixture closes it
    window.close()


def test_the_open_picker_scrolls_inside_the_dock_and_shows_whole_ids(dock, ui):
    _, _, template_picker, _ = ui
    dock.set_template_choices([template_picker.TemplateChoice(f"2.30-{v}", f"Höchstgeschwindigkeit {v}", "red",
                                                              "circle") for v in (20, 30, 50, 80, 100, 120)]
                              + [template_picker.TemplateChoice("2.41.1", "Gebotene Richtung", "blue", "circle")])
    dock.show_picker(True)
    dock.set_observations([])
    QApplication.processEvents()
    assert dock.minimumSizeHint().height() < 400  # a 1000 px screen keeps room for QGIS
    grid = dock.picker.grid
    metrics = grid.fontMetrics()
    assert all(metrics.horizontalAdvance(i) <= grid.gridSize().width() - 8 for i in dock.picker.visible_ids())
    assert grid.textElideMode() == Qt.ElideNone


def test_decisions_that_change_nothing_are_disabled_and_look_it(dock, ui):
    _, review_item, _, _ = ui
    dock.show_item(review_item.ReviewItem("signs", 4, "signs · sign 4", template_id="1.01", status="accepted",
                                          reviewed=True, pair_id="000004", position=(1.0, 2.0, 3.0)))
    assert not dock.buttons["accept"].isEnabled() and dock.buttons["reject"].isEnabled()
    dock.show_item(review_item.ReviewItem("signs", 5, "signs · sign 5", template_id="1.01", status="rejected",
                                          reviewed=True, pair_id="000004"))
    assert dock.buttons["accept"].isEnabled() and not dock.buttons["reject"].isEnabled()
    assert not dock.buttons["zoom"].isEnabled()  # no position
    assert ":enabled" in dock.buttons["accept"].styleSheet()  # the colour is not painted on a disabled button
    dock.set_navigation_enabled(False)
    assert not any(dock.buttons[n].isEnabled() for n in ("previous", "next", "next_review", "add_sign"))


def test_no_stale_image_and_the_caption_names_the_shown_pair(dock, ui):
    _, review_item, _, _ = ui
    assert dock.image_view.has_image() and dock.image_caption.text() == "Image: pair 000004"
    other = QImage(200, 100, QImage.Format_RGB32)
    other.fill(QColor(10, 200, 10))
    dock.set_image("000009", other)  # another pair from the pair box
    assert "pair 000009" in dock.image_caption.text() and "from pair 000004" in dock.image_caption.text()
    dock.show_item(review_item.ReviewItem("detections", 8, "detections · feature 8", pair_id="000006"))
    assert not dock.image_view.has_image()  # until the new feature's image arrives
    dock.show_empty("nothing selected")
    assert not dock.image_view.has_image() and dock.image_caption.text() == ""


def test_progress_shows_what_is_left_to_review(dock):
    dock.set_progress(3, 12, 20)
    assert dock.progress.isVisibleTo(dock) and dock.progress.text() == "3 to review · 12 of 20 reviewed"
    assert dock.progress.value() == 12 and dock.progress.maximum() == 20


def test_wheel_zoom_in_the_full_frame_stays_when_the_dock_changes_size(dock):
    from qgis.PyQt.QtCore import QPointF
    from qgis.PyQt.QtGui import QWheelEvent

    view = dock.image_view
    centre = QPointF(view.viewport().rect().center())
    event = QWheelEvent(centre, view.viewport().mapToGlobal(QPoint(0, 0)), QPoint(0, 0), QPoint(0, 360),
                        Qt.NoButton, Qt.NoModifier, Qt.NoScrollPhase, False)
    QApplication.sendEvent(view.viewport(), event)
    zoomed = view.transform().m11()
    dock.resize(dock.width() + 60, dock.height() - 40)  # labels re-wrapping change the dock's layout
    QApplication.processEvents()
    assert view.transform().m11() == pytest.approx(zoomed)
    QTest.mouseDClick(view.viewport(), Qt.LeftButton)  # double click: back to the crop
    assert view.transform().m11() < zoomed


def press(key, modifier=Qt.NoModifier):
    """A key press where the keyboard is: the widget with the focus, as a user's key reaches it."""
    QTest.keyClick(QApplication.focusWidget(), key, modifier)


def reclassifiable(dock, ui):
    _, review_item, _, _ = ui
    dock.show_item(review_item.ReviewItem(
        "signs", 5, "signs · sign 5", template_id="2.30-50", colour="red", shape="circle", status="review",
        alternatives=[("2.30-80", 0.31), ("1.01", 0.05)], observations=[]))
    dock.image_view.setFocus()
    QApplication.processEvents()


def test_reclassify_by_keys_c_then_1_takes_the_first_next_choice(dock, ui):
    rec = Recorder(dock)
    reclassifiable(dock, ui)
    press(Qt.Key_C)
    assert dock.picker_box.isVisible() and dock.buttons["reclassify"].isChecked()
    assert QApplication.focusWidget() is dock.picker.grid  # not the search box: keys stay keys
    press(Qt.Key_2)
    assert rec.calls == [("reclassifyRequested", "1.01")]
    press(Qt.Key_C)
    press(Qt.Key_3)  # no third choice: nothing
    press(Qt.Key_1)
    assert rec.calls == [("reclassifyRequested", "1.01"), ("reclassifyRequested", "2.30-80")]
    dock.show_picker(False)
    press(Qt.Key_1)  # the picker closed: 1 reclassifies nothing
    assert len(rec.calls) == 2


def test_escape_closes_the_picker_and_the_decision_keys_act_while_it_is_open(dock, ui):
    rec = Recorder(dock)
    reclassifiable(dock, ui)
    press(Qt.Key_C)
    press(Qt.Key_A)  # a decision, not text in the search box
    press(Qt.Key_R)
    assert rec.calls == [("acceptRequested",), ("rejectRequested",)] and dock.picker.search.text() == ""
    assert dock.picker_box.isVisible()
    press(Qt.Key_Escape)
    assert not dock.picker_box.isVisible() and not dock.buttons["reclassify"].isChecked()
    assert dock.isAncestorOf(QApplication.focusWidget())  # the keys still reach the dock
    press(Qt.Key_N)
    assert rec.calls[-1] == ("nextRequested",)
    press(Qt.Key_C)  # C toggles: open, then closed again
    press(Qt.Key_C)
    assert not dock.picker_box.isVisible()


def test_typing_in_the_open_picker_searches_and_enter_reclassifies_as_the_match(dock, ui):
    rec = Recorder(dock)
    reclassifiable(dock, ui)
    press(Qt.Key_C)
    dock.picker.set_filter("", "", "")
    for key in (Qt.Key_K, Qt.Key_U, Qt.Key_R, Qt.Key_V, Qt.Key_E):  # U and R are shortcuts once typing started
        press(key)
    assert QApplication.focusWidget() is dock.picker.search and dock.picker.search.text() == "kurve"
    assert dock.picker.visible_ids() == ["1.01"] and rec.calls == []
    press(Qt.Key_Return)
    assert rec.calls == [("reclassifyRequested", "1.01")]
    dock.show_picker(False)
    press(Qt.Key_C)
    press(Qt.Key_Slash)  # to search for an id starting with a digit (1-3 choose)
    assert QApplication.focusWidget() is dock.picker.search and dock.picker.search.text() == ""
    QTest.keyClicks(dock.picker.search, "2.37")
    assert dock.picker.visible_ids() == ["2.37"]
    press(Qt.Key_Escape)  # closes the picker from the search box too
    assert not dock.picker_box.isVisible()


def test_a_search_starting_with_a_letter_qgis_binds_is_a_search(dock, ui):
    """QGIS binds S (toggle snapping), T (tracing) and Ctrl+F (a modal filter dialog) in its main window: a
    search's first letter must not reach them."""
    from qgis.PyQt.QtWidgets import QAction, QMainWindow

    window = QMainWindow()
    snapping = QAction("Toggle Snapping", window)
    snapping.setShortcut("S")  # as QGIS has it: a window shortcut
    window.addAction(snapping)
    toggled = []
    snapping.triggered.connect(lambda: toggled.append(True))
    window.addDockWidget(Qt.RightDockWidgetArea, dock)
    window.show()
    QApplication.setActiveWindow(window)
    reclassifiable(dock, ui)
    press(Qt.Key_S)  # the picker closed: S is QGIS's
    assert toggled == [True]
    press(Qt.Key_C)
    dock.picker.set_filter("", "", "")
    for key in (Qt.Key_S, Qt.Key_T, Qt.Key_O, Qt.Key_P):
        press(key)
    assert dock.picker.search.text() == "stop" and toggled == [True]
    window.removeDockWidget(dock)
    dock.setParent(None)  # the fixture closes it
    window.close()


def _inside_viewport(dock, widget) -> bool:
    viewport = dock.scroll.viewport()
    top_left = widget.mapTo(viewport, QPoint(0, 0))
    return top_left.y() >= 0 and top_left.y() + widget.height() <= viewport.height()


def test_the_dock_lays_out_in_700_px_with_the_picker_open(dock, ui):
    """On a 1000 px screen the dock gets about 700 px: everything, the open picker included, is in view."""
    _, review_item, _, _ = ui
    dock.resize(420, 700)
    dock.show_item(review_item.ReviewItem(
        "signs", 5, "signs · sign 5 · 3 of 13 · 2 to review", template_id="2.30-50", name="Höchstgeschwindigkeit",
        colour="red", shape="circle", format="normal", status="review", pair_id="000004", time=0.8,
        review_reason="seen in one pair only", alternatives=[("2.30-80", 0.31), ("1.01", 0.05), ("2.37", 0.02)],
        extra=[("observations", "4"), ("vote share", "0.90")],
        observations=[review_item.ObservationView(f"00000{i}", f"00000{i}\n0.8") for i in range(4)]))
    dock.set_progress(2, 1, 13)
    QApplication.processEvents()
    scroll = dock.scroll.verticalScrollBar()
    assert scroll.maximum() == 0  # nothing below the fold
    assert all(_inside_viewport(dock, dock.buttons[name]) for name in dock.buttons)
    dock.show_picker(True)
    QApplication.processEvents()
    assert scroll.maximum() == 0
    for widget in (dock.picker.suggestions, dock.picker.search, dock.picker.grid, dock.buttons["accept"],
                   dock.image_view):
        assert widget.isVisible() and _inside_viewport(dock, widget), widget
    assert dock.image_view.height() >= 150
