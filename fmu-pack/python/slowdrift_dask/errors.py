"""The two kinds of failure of a run on a worker."""


class RunFailed(Exception):
    """The model refused or failed this (case, seed): recorded as a failed run with this
    message, never retried within the campaign (a resumed campaign runs it again)."""
