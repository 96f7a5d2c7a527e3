"""``dpemu score``: the pool pack's integer physics against the float reference (DESIGN.md section 6).

cases (the scenarios) -> run (one case on the emulator, judged by seeded, endtoend and direct) ->
sweep (many cases over processes or a Dask cluster) -> report (rows, JSON, pictures); metrics
holds each row and its pass range.
"""
MODELS = ("motion", "ball-ball", "cushion", "cue", "shots")
