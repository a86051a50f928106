"""The comments FreeCAD's operation base writes at the head of every operation's path, made valid G-code.

The base opens the commands with "(Label)" and "(Comment)" as typed. A G-code comment ends at its first ')'
and cannot nest, so a label such as "planes 30° (study)" gave "(planes 30° study))": Path.Command drops the
inner '(' and keeps both ')', and a controller reads a stray ')' after the comment.
"""
import Path


def comment_text(text):
    """`text` as a G-code comment may hold it: parentheses become brackets, line breaks spaces."""
    return str(text).replace("(", "[").replace(")", "]").replace("\r", " ").replace("\n", " ")


def mend_leading_comments(commandlist, obj):
    """Rewrites the base's "(Label)" and "(Comment)" commands at the head of `commandlist` in place."""
    texts = [obj.Label] + ([obj.Comment] if getattr(obj, "Comment", "") else [])
    for index, text in enumerate(texts):
        if index < len(commandlist) and commandlist[index].Name.startswith("("):
            commandlist[index] = Path.Command("(%s)" % comment_text(text))
