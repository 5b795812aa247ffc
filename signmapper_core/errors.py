"""Exceptions of the core, each carrying enough context to name the culprit."""

from __future__ import annotations


class InputFileError(ValueError):
    """An input file is missing, malformed or contradicts another; the message names the file (and line and
    field where there is one) and what is wrong. ``reason`` is the message without the place."""

    def __init__(self, path, message: str, line: int | None = None, field: str | None = None):
        self.path = str(path)
        self.line = line
        self.field = field
        self.reason = message
        where = self.path
        if line is not None:
            where += f", line {line}"
        if field is not None:
            where += f", field '{field}'"
        super().__init__(f"{where}: {message}")


class DriveFormatError(InputFileError):
    """A drive folder breaks ``drive-format.md``; the message names file, line and field."""


class ImageReadError(DriveFormatError):
    """An image or depth map exists but cannot be decoded or has the wrong size."""


class MappingError(RuntimeError):
    """A run whose output could not be trusted, e.g. because too many pairs could not be read.

    ``limit_exceeded`` tells a run stopped by the allowed share of skipped pairs
    (raising the share may help) from one where no pair could be mapped at all (it cannot).
    """

    def __init__(self, message: str, limit_exceeded: bool = False):
        super().__init__(message)
        self.limit_exceeded = limit_exceeded


class ImportInputError(InputFileError):
    """An importer's input (images, calibration, poses, CRS) is missing, malformed or contradicts another input.

    Not a :class:`DriveFormatError`: the drive folder is what the import writes, not what it reads.
    """


class ClusterError(RuntimeError):
    """A Dask cluster cannot map the drive: Dask missing, no scheduler at the address, no worker or a worker
    without the core, the scheduler lost; the message names the address and what to do."""


class OutputFileError(ValueError):
    """An output cannot be written as asked (not .gpkg, an existing file that is no GeoPackage, a layer of the
    user's in the way); the message names the file and what to do."""


class OutputBusyError(OutputFileError):
    """Another run (a live process, or another task of this one) is writing the same output right now."""


class OutputWriteError(OutputFileError):
    """Writing an output failed part way (disk full, the file system refused): the partial output was dropped,
    an earlier output is as it was; the message names the file, what was being written and why."""
