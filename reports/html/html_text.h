#pragma once
// Text into HTML. svgEscape's XML escaping (& < > " ' as entities, XML-forbidden controls as '?')
// is also right for HTML5 text and double- or single-quoted attribute values — &apos; is an HTML5
// named reference — so the page and its inline plots share one escaper; DEL, which HTML5 flags as
// a control character though XML allows it, becomes '?' as well.
#include <string>
#include <string_view>

namespace cyclecert::html {

std::string htmlEscape(std::string_view text);

// The page as valid UTF-8: each byte that does not start a well-formed sequence (a stray
// continuation byte, a truncated or overlong sequence, a surrogate, beyond U+10FFFF) becomes
// U+FFFD. Report text comes from engines' output; markup is ASCII, so this never changes markup.
std::string validUtf8(std::string_view text);

// A fragment identifier from arbitrary text: [A-Za-z0-9._-] kept, every other byte '_' (an id
// that needs no escaping in href="#…" and no quoting in CSS).
std::string anchorName(std::string_view text);

}  // namespace cyclecert::html
