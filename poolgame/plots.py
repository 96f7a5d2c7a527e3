"""Pictures of the pool table (matplotlib, an optional extra: ``pip install dpemu[plot]``): a shot's
paths and events, and the score's integer-against-float paths, error histograms and error growth.
The table is seen from above with +x to the right and +z down, as in the game looking down with
north up."""
from __future__ import annotations

import math

import numpy as np

from poolgame.physics.constants import BALL_RADIUS, CORNER_OPENING, SIDE_OPENING_HALF, TABLE_LENGTH, TABLE_WIDTH

L_MM, W_MM, R_MM = TABLE_LENGTH * 1000, TABLE_WIDTH * 1000, BALL_RADIUS * 1000
CUSHION_MM, RAIL_MM = 50.0, 110.0
CLOTH, CUSHION, RAIL, POCKET = "#1b6e3a", "#145a2e", "#5b3a1e", "#0b0b0b"
SOLIDS = {0: "#f4f1e6", 1: "#f2c300", 2: "#1f4fbf", 3: "#d0231d", 4: "#5a2a8a", 5: "#f07f12", 6: "#137a3c",
          7: "#7b1f1f", 8: "#111111"}
EVENT_MARKERS = {"ball": ("o", "ball-ball"), "cushion": ("D", "cushion"), "pocket": ("v", "pocket")}


class MissingMatplotlib(RuntimeError):
    pass


def pyplot():
    """matplotlib's pyplot on the file-only Agg backend, or MissingMatplotlib saying how to get it."""
    try:
        import matplotlib
    except ImportError:
        raise MissingMatplotlib("plots need matplotlib: pip install 'dpemu[plot]' (or pip install matplotlib)") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def ball_colour(ball: int) -> str:
    return SOLIDS[ball if ball <= 8 else ball - 8]


def draw_table(ax) -> None:
    """Rails, cushions, cloth and the six pockets, in mm from the playing area's corner."""
    from matplotlib.patches import Circle, Rectangle
    edge = CUSHION_MM + RAIL_MM
    ax.add_patch(Rectangle((-edge, -edge), L_MM + 2 * edge, W_MM + 2 * edge, color=RAIL, zorder=0))
    ax.add_patch(Rectangle((-CUSHION_MM, -CUSHION_MM), L_MM + 2 * CUSHION_MM, W_MM + 2 * CUSHION_MM, color=CUSHION,
                           zorder=0))
    ax.add_patch(Rectangle((0, 0), L_MM, W_MM, color=CLOTH, zorder=0))
    corner, side = CORNER_OPENING * 1000, SIDE_OPENING_HALF * 1000
    for x, z, r in [(0, 0, corner * 0.7), (L_MM, 0, corner * 0.7), (0, W_MM, corner * 0.7), (L_MM, W_MM, corner * 0.7),
                    (L_MM / 2, -side * 0.35, side), (L_MM / 2, W_MM + side * 0.35, side)]:
        ax.add_patch(Circle((x, z), r, color=POCKET, zorder=1))
    for x in (L_MM / 8 * k for k in (1, 2, 3, 5, 6, 7)):   # the diamonds on the rails
        for z in (-CUSHION_MM - RAIL_MM / 2, W_MM + CUSHION_MM + RAIL_MM / 2):
            ax.plot(x, z, marker="D", color="#e8dcc0", markersize=3, zorder=1)
    ax.plot(L_MM / 4, W_MM / 2, marker="o", color="#d8e8d8", markersize=2, zorder=1)   # the head spot
    ax.set_xlim(-edge, L_MM + edge)
    ax.set_ylim(W_MM + edge, -edge)            # +z down
    ax.set_aspect("equal")
    ax.axis("off")


def draw_ball(ax, ball: int, x: float, z: float, alpha: float = 1.0, label: bool = True) -> None:
    from matplotlib.patches import Circle, Rectangle
    colour = ball_colour(ball)
    disc = Circle((x, z), R_MM, facecolor=colour if ball <= 8 else "#f4f1e6", edgecolor="#222222", linewidth=0.6,
                  alpha=alpha, zorder=4)
    ax.add_patch(disc)
    if ball > 8:                               # a stripe: a coloured band across the white ball
        band = Rectangle((x - R_MM, z - R_MM * 0.55), 2 * R_MM, 1.1 * R_MM, facecolor=colour, alpha=alpha, zorder=4)
        band.set_clip_path(disc)
        ax.add_patch(band)
    if label and ball > 0:
        ax.text(x, z, str(ball), ha="center", va="center", fontsize=5, color="white" if ball in (2, 4, 7, 8) else "black",
                zorder=5, alpha=alpha)


def shot_picture(path, ids, positions, events, title: str) -> None:
    """``positions``: (ticks + 1, balls, 2) mm from the start; ``events``: Event.to_json dicts."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(12, 6.6))
    draw_table(ax)
    for j, ball in enumerate(ids):
        track = positions[:, j]
        if np.ptp(track, axis=0).max() > 0.5:
            ax.plot(track[:, 0], track[:, 1], color=ball_colour(ball), linewidth=1.2, alpha=0.9, zorder=2,
                    path_effects=_outline(plt))
            draw_ball(ax, ball, *track[0], alpha=0.35, label=False)
    shown = set()
    for event in events:
        marker, name = EVENT_MARKERS[event["kind"]]
        ax.plot(event["x_mm"], event["z_mm"], marker=marker, markersize=4, markerfacecolor="none",
                markeredgecolor="white", zorder=3, label=None if name in shown else name, linestyle="none")
        shown.add(name)
    pocketed = {e["ball"] for e in events if e["kind"] == "pocket"}
    for j, ball in enumerate(ids):
        if ball not in pocketed:
            draw_ball(ax, ball, *positions[-1, j])
    if shown:
        ax.legend(loc="lower right", ncol=3, fontsize=8, facecolor=CLOTH, edgecolor=CUSHION, labelcolor="white")
    ax.set_title(title, fontsize=10)
    fig.savefig(path, dpi=130, bbox_inches="tight", facecolor="white")
    plt.close(fig)


def _outline(plt):
    from matplotlib import patheffects
    return [patheffects.Stroke(linewidth=2.2, foreground="#0a3a1a"), patheffects.Normal()]


# ---------------------------------------------------------------------------- dpemu score
def _grid(plt, count: int, cols: int, width: float, height: float):
    """A figure of ``count`` panels in rows of ``cols``; the unused panels hidden."""
    rows = math.ceil(count / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(width, height * rows), squeeze=False)
    for ax in list(axes.flat)[count:]:
        ax.axis("off")
    return fig, list(axes.flat)[:count]


def score_paths(path, results, limit: int = 6) -> None:
    """The integer paths (solid) and the float's (seeded dashed, end-to-end dotted) of a few cases."""
    plt = pyplot()
    shown = [r for r in results if r.paths is not None][:limit]
    if not shown:
        return
    fig, axes = _grid(plt, len(shown), 2, 14, 3.9)
    for ax, result in zip(axes, shown):
        draw_table(ax)
        p = result.paths
        for j, ball in enumerate(p["ids"]):
            track = p["int"][:, j]
            if np.ptp(track, axis=0).max() <= 0.5:
                continue
            colour = ball_colour(ball)
            ax.plot(track[:, 0], track[:, 1], color=colour, linewidth=2.2, alpha=0.8, zorder=2)
            for mode, style in (("seeded", "--"), ("end-to-end", ":")):
                if p[mode] is not None:
                    ax.plot(p[mode][:, j, 0], p[mode][:, j, 1], color="black" if ball == 0 else "white",
                            linestyle=style, linewidth=0.9, zorder=3)
            draw_ball(ax, ball, *track[-1])
        ax.set_title(result.name, fontsize=9)
    fig.suptitle("integer paths (thick) with the float reference: seeded (dashed), end-to-end (dotted)", fontsize=11)
    fig.savefig(path, dpi=110, bbox_inches="tight", facecolor="white")
    plt.close(fig)


def histograms(path, rows) -> None:
    """One histogram per metric with samples, its pass limit drawn in red."""
    plt = pyplot()
    rows = [r for r in rows if r.values]
    if not rows:
        return
    fig, axes = _grid(plt, len(rows), 4, 16, 3.0)
    for ax, row in zip(axes, rows):
        values = np.asarray(row.values, float)
        values = values[np.isfinite(values)]
        ax.hist(values, bins=30, color="#2f7d4f" if row.passed else "#b03030")
        m = row.metric
        for limit in (m.low, m.high):
            if m.scored and math.isfinite(limit):
                ax.axvline(limit, color="red", linewidth=1)
        ax.set_title(f"{m.text}\n({m.mode}, {m.unit})", fontsize=8)
        ax.tick_params(labelsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100, facecolor="white")
    plt.close(fig)


def growth(path, results) -> None:
    """Distance between the integer and the float position of each moving ball, tick by tick:
    seeded (restarted at every event) and end to end (one float shot from the strike)."""
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(14, 4.5), sharey=False)
    for ax, mode in zip(axes, ("seeded", "end-to-end")):
        for result in results:
            p = result.paths
            if p is None or p[mode] is None:
                continue
            ints, floats = p["int"][1:], p[mode]
            for j in range(ints.shape[1]):
                if np.ptp(ints[:, j], axis=0).max() <= 0.5:
                    continue
                error = np.linalg.norm(ints[:, j] - floats[:, j], axis=1)
                ax.plot(np.arange(1, len(error) + 1), error, linewidth=0.7, alpha=0.6)
        ax.set_yscale("symlog", linthresh=1e-3)
        ax.set_xlabel("physics tick after the strike")
        ax.set_ylabel("integer - float distance (mm)")
        ax.set_title(f"{mode}: error along the path", fontsize=10)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100, facecolor="white")
    plt.close(fig)
