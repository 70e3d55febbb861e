"""What the bench scripts share: writing a figure or a text file whole or not at all."""
import os


def _replace_whole(path, write):
    """Calls write(tmp) for a temporary file beside path, then renames it into place; the
    temporary never stays behind. It keeps path's extension, from which savefig takes the
    format."""
    tmp = f"{path}.tmp-{os.getpid()}{os.path.splitext(path)[1]}"
    try:
        write(tmp)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def write_atomically(fig, path):
    """Saves fig to path through a temporary file beside it, renamed into place. The same
    figure gives the same bytes: an SVG carries no date, and its element ids are hashed
    from a fixed salt instead of a random one."""
    import matplotlib   # here, not at the top: the scripts that only write text need not load it
    svg = path.endswith(".svg")
    with matplotlib.rc_context({"svg.hashsalt": "raster"}):
        _replace_whole(path, lambda tmp: fig.savefig(tmp, dpi=130, metadata={"Date": None} if svg else None))


def write_text_atomically(text, path):
    """Writes text to path through a temporary file beside it, renamed into place."""
    def write(tmp):
        with open(tmp, "w") as f:
            f.write(text)
    _replace_whole(path, write)
