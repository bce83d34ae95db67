package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.StudentResult;
import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.preview.HeadlessChromium;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.assertj.core.data.Offset;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.support.ui.ExpectedConditions;

/**
 * The cohort's {@code index.html} opened from disk in a real headless Chromium, as course staff
 * open it: no server, nothing from the network. Skipped, with a message saying how to enable it,
 * where Chromium is not installed.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@Order(21)   // one of the longest classes: it starts early (junit-platform.properties)
class CohortPageBrowserTest {

    private static final Duration PATIENCE = Duration.ofSeconds(60);   // a slow shared CI machine

    private Path report;

    private HeadlessChromium browser;
    private List<StudentResult> results;

    @BeforeAll
    void writeTheReportAndStartTheBrowser(@TempDir Path folder) throws IOException {
        report = folder;
        results = SmallCohort.writeImages(report);
        CohortReport.write(report, results, SmallCohort::grade);
        if (HeadlessChromium.isInstalled()) {
            browser = HeadlessChromium.start();
        }
    }

    @AfterAll
    void stop() throws IOException {
        if (browser != null) {
            browser.close();
        }
    }

    @BeforeEach
    void openTheIndexFromDisk() {
        HeadlessChromium.assumeInstalled();
        browser.driver.get(report.resolve(CohortReport.INDEX).toUri().toString());
        browser.waitUpTo(PATIENCE).until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-status", "ready"));
    }

    private Object script(String code, Object... arguments) {
        return ((JavascriptExecutor) browser.driver).executeScript(code, arguments);
    }

    private List<String> column(int index) {
        return browser.driver.findElements(By.cssSelector("#students tbody tr")).stream()
                .map(row -> row.findElements(By.tagName("td")).get(index).getText()).toList();
    }

    private void clickHeading(String heading) {
        browser.driver.findElement(By.xpath("//th/button[text()='" + heading + "']")).click();
    }

    @Test
    void thePageShowsHowManyOfTheResultsGivenPassed() {
        long passed = results.stream().filter(StudentResult::passed).count();
        assertThat(browser.driver.findElement(By.id("passed-count")).getText()).isEqualTo(String.valueOf(passed));
        assertThat(browser.driver.findElement(By.id("total-count")).getText())
                .isEqualTo(String.valueOf(results.size()));
        assertThat(browser.driver.findElements(By.cssSelector("#students tbody tr"))).hasSize(results.size());
        assertThat(column(2).stream().filter("pass"::equals).count()).isEqualTo(passed);
    }

    @Test
    void theChartDrawsABarOfVisibleSizeForEveryDiagnosisOfAFailure() {
        Map<String, Long> failures = results.stream().filter(result -> !result.passed())
                .collect(Collectors.groupingBy(result -> result.diagnosis().label(), Collectors.counting()));
        List<WebElement> bars = browser.driver.findElements(By.cssSelector("#diagnoses g.bar"));
        assertThat(bars).hasSize(failures.size());
        double widthOfOne = 0;
        for (WebElement bar : bars) {
            WebElement rect = bar.findElement(By.tagName("rect"));
            @SuppressWarnings("unchecked")
            Map<String, Number> box = (Map<String, Number>) script(
                    "const r = arguments[0].getBoundingClientRect(); return {width: r.width, height: r.height};",
                    rect);
            long count = Long.parseLong(bar.getAttribute("data-count"));
            assertThat(count).as(bar.getAttribute("data-label"))
                    .isEqualTo(failures.get(bar.getAttribute("data-label")));
            assertThat(box.get("width").doubleValue()).as("width of " + bar.getAttribute("data-label")).isPositive();
            assertThat(box.get("height").doubleValue()).as("height of " + bar.getAttribute("data-label")).isPositive();
            if (count == 1) {
                widthOfOne = box.get("width").doubleValue();
            }
            assertThat(bar.getText()).as("the bar's label and count").contains(String.valueOf(count));
        }
        double widest = bars.get(0).findElement(By.tagName("rect")).getRect().getWidth();
        assertThat(widest).as("the most common diagnosis's bar, twice as long as a single failure's")
                .isCloseTo(2 * widthOfOne, Offset.offset(2.0));
    }

    @Test
    void clickingTheTimeHeadingSortsByDurationAndAgainReverses() {
        Comparator<StudentResult> byTime = Comparator.comparing(StudentResult::time);
        clickHeading("Time");
        assertThat(column(7)).isEqualTo(durations(byTime));
        clickHeading("Time");
        assertThat(column(7)).isEqualTo(durations(byTime.reversed()));
    }

    private List<String> durations(Comparator<StudentResult> order) {
        return results.stream().sorted(order).map(result -> CohortPage.duration(result.time())).toList();
    }

    @Test
    void clickingTheIdHeadingSortsDigitsByTheirValue() {
        clickHeading("Id");
        assertThat(column(1)).containsExactly("999", "1001", "1002", "1003", "1004", "crsid42");
    }

    @Test
    void clickingTheGradeHeadingSortsByTheMarkAndKeepsTheEarlierOrderAmongEquals() {
        clickHeading("Id");
        clickHeading("Grade");
        assertThat(column(4)).containsExactly("0.00", "0.00", "0.00", "0.00", "1.00", "1.00");
        assertThat(column(1)).containsExactly("1002", "1003", "1004", "crsid42", "999", "1001");
    }

    @Test
    void aCohortOfThreeHundredLoadsOnlyTheThumbnailsNearTheViewAndSortsWhole(@TempDir Path folder)
            throws IOException {
        List<StudentResult> cohort = SmallCohort.large(folder, 300);
        CohortReport.write(folder, cohort, SmallCohort::grade);
        browser.driver.get(folder.resolve(CohortReport.INDEX).toUri().toString());
        browser.waitUpTo(PATIENCE).until(ExpectedConditions.attributeToBe(By.tagName("body"), "data-status", "ready"));
        // The load event waits for every image that is not lazy; lazy ones below the fold wait for a scroll.
        browser.waitUpTo(PATIENCE).until(driver -> "complete".equals(script("return document.readyState;")));
        String loaded = "return Array.from(document.querySelectorAll('img.thumbnail'))"
                + ".filter(image => image.complete && image.naturalWidth > 0).length;";
        assertThat(((Number) script(loaded)).intValue()).as("thumbnails loaded before any scroll")
                .isPositive().isLessThan(cohort.size());
        WebElement last = browser.driver.findElement(By.cssSelector("#students tbody tr:last-child img.thumbnail"));
        script("arguments[0].scrollIntoView();", last);
        browser.waitUpTo(PATIENCE).until(driver -> (Boolean) script(
                "return arguments[0].complete && arguments[0].naturalWidth > 0;", last));

        clickHeading("Time");
        assertThat(column(7)).isEqualTo(cohort.stream().sorted(Comparator.comparing(StudentResult::time))
                .map(result -> CohortPage.duration(result.time())).toList());
    }

    @Test
    void markupInANameIsShownAsTextAndRunsNothing() {
        assertThat(column(0)).contains(SmallCohort.HOSTILE_NAME);
        assertThat(script("return window.xssRan === undefined;")).isEqualTo(true);
    }

    @Test
    void aThumbnailShowsTheHeatMapAndLeadsToTheStudentsFeedbackWithItsImages() {
        WebElement thumbnail = browser.driver.findElement(By.cssSelector("img.thumbnail"));
        script("arguments[0].scrollIntoView();", thumbnail);
        browser.waitUpTo(PATIENCE).until(driver -> (Boolean) script(
                "return arguments[0].complete && arguments[0].naturalWidth > 0;", thumbnail));
        thumbnail.click();
        browser.waitUpTo(PATIENCE).until(ExpectedConditions.titleContains("Tick 1 feedback"));
        assertThat(browser.driver.findElement(By.tagName("h1")).getText()).contains("Mallory");
        List<WebElement> images = browser.driver.findElements(By.cssSelector(".images img"));
        assertThat(images).hasSize(3);
        for (WebElement image : images) {
            browser.waitUpTo(PATIENCE).until(driver -> (Boolean) script(
                    "return arguments[0].complete && arguments[0].naturalWidth === 16;", image));
        }
        assertThat(script("return window.xssRan === undefined;")).isEqualTo(true);
    }
}
