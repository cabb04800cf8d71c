"""The browser preview's front end (scripts/serve.py): message framing checks."""
