"""A detector that raises deep inside for one pair: importable by name, so worker processes can run it."""

from signmapper_core.pipeline import detect_pair


def detect_failing_at(failing_pose, left, depth, right, camera, pose, *args, **kwargs):
    """``detect_pair``, except for the pair at ``failing_pose`` (bind it with functools.partial)."""
    if pose == failing_pose:
        return [][1]
    return detect_pair(left, depth, right, camera, pose, *args, **kwargs)


def exit_at(failing_pose, left, depth, right, camera, pose, *args, **kwargs):
    """``detect_pair``, except that the process ends at once at ``failing_pose`` (as when killed for memory)."""
    import os

    if pose == failing_pose:
        os._exit(9)
    return detect_pair(left, depth, right, camera, pose, *args, **kwargs)
