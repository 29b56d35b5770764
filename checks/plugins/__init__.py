"""The pytest plugins of the suite, listed in the root ``conftest.py``."""
