package gfx.tick1.command.preview;

import com.sun.net.httpserver.Headers;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;

/**
 * Decides which requests the previewer answers. Binding to 127.0.0.1 keeps other machines out;
 * this keeps out other web sites open in the same browser:
 * <ul>
 *   <li>the Host header must name this server, which defeats DNS rebinding (a hostile name that
 *       is made to resolve to 127.0.0.1 still arrives with that name in Host);</li>
 *   <li>an Origin header, which browsers send with every POST and cross-origin fetch, must be
 *       this server's own, so another site's page can neither upload scenes nor read answers;</li>
 *   <li>a Sec-Fetch-Site header saying another site made the request is refused, which also
 *       covers requests browsers send without an Origin (images, scripts), except the user
 *       following a link to the page itself.</li>
 * </ul>
 */
final class LoopbackGuard {

    private final Set<String> hosts;
    private final Set<String> origins;

    /** Accepts the names under which a browser on this machine reaches 127.0.0.1:{@code port}. */
    LoopbackGuard(int port) {
        hosts = Set.of("127.0.0.1:" + port, "localhost:" + port);
        origins = Set.of("http://127.0.0.1:" + port, "http://localhost:" + port);
    }

    /** Why the request must be refused, empty when it may be answered. */
    Optional<String> refusal(Headers headers) {
        List<String> host = headers.get("Host");
        if (host == null || host.size() != 1 || !hosts.contains(host.get(0).toLowerCase(Locale.ROOT))) {
            return Optional.of("Host " + host + " is not this server");
        }
        List<String> origin = headers.get("Origin");
        if (origin != null && (origin.size() != 1 || !origins.contains(origin.get(0).toLowerCase(Locale.ROOT)))) {
            return Optional.of("Origin " + origin + " is not this server");
        }
        String site = headers.getFirst("Sec-Fetch-Site");
        boolean navigation = "navigate".equals(headers.getFirst("Sec-Fetch-Mode"));
        if (("cross-site".equals(site) || "same-site".equals(site)) && !navigation) {
            return Optional.of("request made by another site's page");
        }
        return Optional.empty();
    }
}
