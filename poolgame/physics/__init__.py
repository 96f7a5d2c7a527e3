"""Float64 reference physics of the pool datapack: the formulas the integer physics is scored
against. One module per model or event; all constants in :mod:`poolgame.physics.constants`.

Vectors are 2-D numpy arrays in the table plane (x along the long side, z along the short side,
y up). A ball's spin is kept as surface velocities: ``w = R (omega x y)`` (so the slip is
``v - w``) and ``wy = R omega_y``. Equations follow seed/pool-models.md with seed/errata.md.
"""
