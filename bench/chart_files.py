"""What the chart scripts share: writing a figure whole or not at all."""
import os


def write_atomically(fig, path):
    """Saves fig to path through a temporary file beside it, renamed into place."""
    tmp = f"{path}.tmp-{os.getpid()}{os.path.splitext(path)[1]}"
    try:
        fig.savefig(tmp, dpi=130)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
