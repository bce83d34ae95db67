package gfx.tick1.command.preview;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Base64;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The page and three.js, read from the classpath (never from disk): the page's own three files
 * from this package's resources, and three.js from its WebJar, whose files live under
 * {@code META-INF/resources/webjars/three/<version>/} exactly as in the npm package.
 */
final class StaticFiles {

    /** A file to send: its bytes and its Content-Type. */
    record File(byte[] bytes, String contentType) {
    }

    private static final String PAGE_DIRECTORY = "gfx/tick1/command/preview/";
    private static final Map<String, String> PAGE = Map.of(
            "/", "index.html",
            "/preview.js", "preview.js",
            "/preview.css", "preview.css");
    /** URL prefix under which the page's import map expects three.js. */
    static final String THREE_PREFIX = "/three/";
    // Letters, digits and single dots between names: no "..", no "//", no backslash, and only
    // the JavaScript modules the page imports.
    private static final Pattern THREE_FILE =
            Pattern.compile("([A-Za-z0-9_-]+/)*[A-Za-z0-9_-]+(\\.[A-Za-z0-9_-]+)*\\.js");
    private static final Pattern IMPORT_MAP =
            Pattern.compile("<script type=\"importmap\">(.*?)</script>", Pattern.DOTALL);

    private final String threeDirectory;

    StaticFiles() {
        threeDirectory = "META-INF/resources/webjars/three/" + webJarVersion("org.webjars.npm", "three") + "/";
    }

    /** The file served at {@code path}, empty when there is none. */
    Optional<File> find(String path) {
        String page = PAGE.get(path);
        if (page != null) {
            return Optional.of(new File(read(PAGE_DIRECTORY + page), contentType(page)));
        }
        if (path.startsWith(THREE_PREFIX)) {
            String name = path.substring(THREE_PREFIX.length());
            if (THREE_FILE.matcher(name).matches()) {
                return readIfPresent(threeDirectory + name).map(bytes -> new File(bytes, contentType(name)));
            }
        }
        return Optional.empty();
    }

    /**
     * The Content-Security-Policy source for the page's one inline script, its import map (an
     * import map cannot be an external file): {@code 'sha256-<base64 of its SHA-256>'}.
     */
    String importMapHash() {
        String html = new String(read(PAGE_DIRECTORY + "index.html"), StandardCharsets.UTF_8);
        Matcher importMap = IMPORT_MAP.matcher(html);
        if (!importMap.find()) {
            throw new IllegalStateException("index.html has no import map");
        }
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256")
                    .digest(importMap.group(1).getBytes(StandardCharsets.UTF_8));
            return "'sha256-" + Base64.getEncoder().encodeToString(digest) + "'";
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }

    private static String contentType(String name) {
        if (name.endsWith(".html")) {
            return "text/html; charset=utf-8";
        }
        if (name.endsWith(".css")) {
            return "text/css; charset=utf-8";
        }
        return "text/javascript; charset=utf-8";
    }

    /** The version of a WebJar on the classpath, from the pom.properties that Maven puts in every jar. */
    private static String webJarVersion(String group, String artifact) {
        Properties properties = new Properties();
        try (InputStream in = open("META-INF/maven/" + group + "/" + artifact + "/pom.properties")) {
            if (in == null) {
                throw new IllegalStateException("the " + group + ":" + artifact + " WebJar is not on the classpath");
            }
            properties.load(in);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return properties.getProperty("version");
    }

    private static byte[] read(String resource) {
        return readIfPresent(resource)
                .orElseThrow(() -> new IllegalStateException(resource + " is missing from the classpath"));
    }

    private static Optional<byte[]> readIfPresent(String resource) {
        try (InputStream in = open(resource)) {
            return in == null ? Optional.empty() : Optional.of(in.readAllBytes());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static InputStream open(String resource) {
        return StaticFiles.class.getClassLoader().getResourceAsStream(resource);
    }
}
