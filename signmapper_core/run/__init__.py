"""Running the mapping of a drive: the pairs through the pipeline in this process, worker processes or Dask."""

# the front ends' (mapsigns, python -m signmapper_core.map) largest share of unreadable pairs before a drive fails,
# in percent (map_drive's max_skipped_share is this / 100)
MAX_SKIPPED_PERCENT = 50.0
