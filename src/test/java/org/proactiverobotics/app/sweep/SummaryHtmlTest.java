package org.proactiverobotics.app.sweep;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** summary.html as written: nothing to fetch, a table by world kind only when generate named a world, any number of missions. */
class SummaryHtmlTest {

    private static SummaryHtml.Row row(int index, String world, String outcome) {
        boolean ok = outcome.equals("MISSION_ACCOMPLISHED");
        return new SummaryHtml.Row(index, world, "safety-first", "none", 1, outcome, ok, "1/1", 10, 0.1, 2, 0, 80, 0,
                ok ? "" : "the battery ran flat", null);
    }

    @Test
    void fetchesNothingTheOnlyAddressIsTheSvgNamespace() throws IOException {
        String page = SummaryHtml.page(List.of(row(1, "rooms-001", "MISSION_ACCOMPLISHED"), row(2, "rooms-002", "BATTERY_DEPLETED")),
                "2 missions");
        Matcher addresses = Pattern.compile("(https?:)?//[a-z0-9.-]+\\.[a-z]{2,}[^\"' )]*").matcher(page);
        while (addresses.find()) {
            assertThat(addresses.group()).isEqualTo("http://www.w3.org/2000/svg");
        }
        assertThat(page).doesNotContain("<link", " src=", "@import", "url(");
    }

    @Test
    void cutsByWorldKindOnlyWhenAWorldIsGeneratesOwn() throws IOException {
        String handNamed = SummaryHtml.page(List.of(row(1, "reference-arena", "MISSION_ACCOMPLISHED"),
                row(2, "short-limit-007", "TIME_LIMIT")), "2 missions");
        assertThat(handNamed).contains("id=\"strategy-noise\"").doesNotContain("id=\"strategy-noise-kind\"",
                "id=\"success-by-kind-strategy\"");
        String generated = SummaryHtml.page(List.of(row(1, "reference-arena", "MISSION_ACCOMPLISHED"),
                row(2, "maze-007", "TIME_LIMIT")), "2 missions");
        assertThat(generated).contains("id=\"strategy-noise-kind\"", "id=\"success-by-kind-strategy\"",
                "<td class=\"text factor\">maze</td>", "<td class=\"text factor\">—</td>");
    }

    @Test
    void aSweepStoppedBeforeAnyMissionEndedStillGetsAPage() throws IOException {
        String page = SummaryHtml.page(List.of(), "0 of 4 missions done: stopped");
        assertThat(page).contains("0 of 4 missions done: stopped", "id=\"success-by-strategy-noise\"", "const ROWS = [];");
    }
}
