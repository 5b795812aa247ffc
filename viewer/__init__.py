"""The drive viewer: steps through a drive's left images with the mapped signs over them and the vehicle on the map.

``controller`` follows the current Sign Mapper layer and wires the dock
(``ui/drive_viewer.py``) to ``frames`` (decoding in the background, ahead of
the user), ``overlays`` (which signs and detections a pair shows) and
``map_items`` (vehicle, view cone and the click-to-open map tool).
"""
