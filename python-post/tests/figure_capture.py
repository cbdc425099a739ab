"""The matplotlib Figure a plot function made, drawn with a renderer, so tests can look at what is on
it (legend entries, line styles, limits, text extents) and not only at the file's bytes."""
from matplotlib.backends.backend_agg import FigureCanvasAgg


def capture_figures(monkeypatch, module):
    """Patch `module.emit_figure`: every figure it is given is appended to the returned list (and still
    written, so the run is the real one)."""
    figures, real = [], module.emit_figure

    def keep(fig, out, *args, **kw):
        figures.append(fig)
        return real(fig, out, *args, **kw)
    monkeypatch.setattr(module, "emit_figure", keep)
    return figures


def renderer_of(fig):
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    return canvas.get_renderer()


def overlap(a, b):
    """Area (pixels²) shared by two Bbox."""
    w = min(a.x1, b.x1) - max(a.x0, b.x0)
    h = min(a.y1, b.y1) - max(a.y0, b.y0)
    return max(w, 0) * max(h, 0)
