"""gjk2d.validate and gjk2d.load_report (docs/python.md, "Validating your own GJK from Python")."""


def validate(fn, **options):
    """Runs fn as a comparison variant through gjk-validate's campaign (not yet implemented)."""
    raise NotImplementedError("gjk2d.validate is not implemented yet")


def load_report(directory):
    """Loads a report directory's report.json as plain dicts (not yet implemented)."""
    raise NotImplementedError("gjk2d.load_report is not implemented yet")
