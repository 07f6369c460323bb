"""The two-panel figure against time that several validation plots share:
a top and a bottom panel over one time axis, gridded, saved as PNG."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def two_panels(height_ratios=(1, 1)):
    """A figure and its (top, bottom) axes sharing the time axis."""
    fig, (top, bottom) = plt.subplots(
        2, 1, figsize=(7, 6), sharex=True,
        gridspec_kw={"height_ratios": list(height_ratios)})
    return fig, top, bottom


def save(fig, top, bottom, path):
    """Grid both panels, label the time axis and write @p path."""
    top.grid(alpha=0.3)
    bottom.grid(alpha=0.3)
    bottom.set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print("wrote", path)
