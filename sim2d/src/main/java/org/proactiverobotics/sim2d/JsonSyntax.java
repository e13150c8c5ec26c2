package org.proactiverobotics.sim2d;

import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A JSON syntax error in this project's words: what is wrong and where (line and column, and the
 * key it was in), without the parser's advice to switch to lenient parsing nor its web link.
 */
public final class JsonSyntax {

    /** Where the parser stopped: {@code at line 2 column 4 path $.arena}. */
    private static final Pattern WHERE = Pattern.compile("at line (\\d+) column (\\d+)(?: path (\\S+))?");

    /** The parser's opening words, and what they mean to someone who wrote the file. */
    private static final List<Map.Entry<String, String>> WHAT = List.of(
            Map.entry("Unterminated object", "an object is not closed, or a ',' is missing between its entries"),
            Map.entry("Unterminated array", "an array is not closed, or a ',' is missing between its items"),
            Map.entry("Unterminated string", "a string has no closing '\"'"),
            Map.entry("Unterminated comment", "comments are not allowed"),
            Map.entry("Unterminated escape sequence", "a '\\' in a string is not followed by an escape"),
            Map.entry("Malformed Unicode escape", "a \\u escape needs four hexadecimal digits"),
            Map.entry("Invalid escape", "a '\\' in a string is followed by something that cannot be escaped"),
            Map.entry("Cannot escape a newline", "a string may not run over a line end"),
            // a raw line end (or tab) inside a string: most often its closing '"' is missing
            Map.entry("Unescaped control characters", "a string runs over a line end or holds a tab (a closing '\"' missing?)"),
            Map.entry("Expected name", "a key in double quotes was expected (a ',' too many before a '}'?)"),
            Map.entry("Expected ':'", "a ':' was expected after the key"),
            Map.entry("Expected value", "a value was expected (a ',' too many before a ']'?)"),
            Map.entry("Unexpected value", "a value stands where none may"),
            Map.entry("End of input", "the file ends before the JSON does (a '}' or ']' missing?)"),
            Map.entry("Nesting limit", "the JSON nests too deeply"),
            Map.entry("Use JsonReader.setStrictness", "not strict JSON: comments, single quotes, unquoted words,"
                    + " NaN or Infinity, ';' or '=' are not allowed"));

    private JsonSyntax() {
    }

    /**
     * @param failure what the JSON parser threw (its cause is looked through)
     * @return e.g. {@code an object is not closed, or a ',' is missing between its entries (line 2,
     *         column 4, in arena)}: one line, no advice of the parser's own
     */
    public static String describe(Throwable failure) {
        Throwable t = failure;
        while (t.getCause() != null && t.getCause() != t) {
            t = t.getCause();
        }
        String text = String.valueOf(t.getMessage()).strip();
        String what = null;
        for (Map.Entry<String, String> e : WHAT) {
            if (text.startsWith(e.getKey())) {
                what = e.getValue();
                break;
            }
        }
        if (what == null) { // the parser's first words, without its position, advice or link
            String first = text.lines().findFirst().orElse(text);
            int at = first.indexOf(" at line ");
            what = at > 0 ? first.substring(0, at) : first;
        }
        Matcher where = WHERE.matcher(text);
        if (!where.find()) {
            return what;
        }
        String path = where.group(3) == null ? "" : where.group(3).replaceFirst("^\\$\\.?", "");
        return what + " (line " + where.group(1) + ", column " + where.group(2) + (path.isEmpty() ? "" : ", in " + path) + ")";
    }
}
