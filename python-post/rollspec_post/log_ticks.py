"""Tick labels of log axes that span less than about two decades: matplotlib labels only the powers
of ten there from one decade on, so a 100-2000 Hz axis read "10², 10³" and nothing between."""
from matplotlib.ticker import LogFormatter, LogFormatterSciNotation

# numdec above the first: powers of ten only; between: 2, 3, 4, 6 of each decade; below the second: all.
MINOR_THRESHOLDS = (2.0, 0.5)


def label_log_axes(ax, plain=()):
    """Minor tick labels on each log axis of `ax`. The formatter reads the span at draw time, so
    limits set later still count. Axes named in `plain` ("x", "y") read 200, 1000 (frequencies), the
    others 2×10², 10³."""
    for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
        if axis.get_scale() != "log":
            continue
        kind = LogFormatter if name in plain else LogFormatterSciNotation
        axis.set_minor_formatter(kind(labelOnlyBase=False, minor_thresholds=MINOR_THRESHOLDS))
        if name in plain:
            axis.set_major_formatter(LogFormatter(labelOnlyBase=True))
