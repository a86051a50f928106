"""Pictures written by examples and reports, and drawn in the GUI's panels. No FreeCAD needed.

One module per subject; import what you use from it:
    common      figures (new_figure, subplots), the tight layout of panel plots, the feed colour map
    curve_nets  curve nets in plan, the part with its curves
    feedrate    feed-rate reports: feed classes and block lengths, feed maps, strategy times
    direction   machining direction: rate per direction, feed scans, direction maps, simulated validation

Figures are made without pyplot (matplotlib.figure.Figure with an Agg canvas, see common.new_figure), so
importing these modules never changes the matplotlib backend of the FreeCAD session they run in. Do not
import matplotlib.pyplot here.
"""
