"""The review dock alone: buttons and shortcuts emit its signals, clicks map to image pixels, the picker filters."""

import pytest
from qgis.PyQt.QtCore import QPoint, Qt
from qgis.PyQt.QtGui import QColor, QImage
from qgis.PyQt.QtTest import QTest
from qgis.PyQt.QtWidgets import QApplication


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
    widget.show_item(review_item.ReviewItem(
        "detections", 3, "detections · feature 3", template_id="2.30-50", name="Höchstgeschwindigkeit 50",
        colour="red", shape="circle", format="normal", size_m=(0.6, 0.6), status="review", pair_id="000004",
        time=0.8, bbox=(80, 30, 40, 40), centroid=(99.5, 49.5), crop=(40, 0, 120, 100), image=image,
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
