"""Helpers that input scripts in different folders of testsuite/Inputs/ share."""
