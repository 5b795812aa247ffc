"""Running the mapping of a drive: the pairs through the pipeline in this process, worker processes or Dask."""
