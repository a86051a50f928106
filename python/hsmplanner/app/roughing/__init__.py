"""5-axis roughing in a FreeCAD document: the test parts and their stocks (parts), the Roughing volume object
(volume), the Volume roughing operation (operation), its program and clearance (commands), and the study of
the five strategies (study). Documents saved before these modules were gathered here name them
hsmplanner.app.roughing_parts, roughing_object, roughing_op…: hsmplanner_legacy_modules resolves those names."""
