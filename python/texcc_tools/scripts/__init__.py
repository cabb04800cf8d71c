"""The code of the commands in scripts/ (each file there is a thin entry point)."""
