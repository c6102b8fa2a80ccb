// syskit doc: filters the index as one types. Plain JavaScript, no network;
// without it the whole list stays visible.
(function () {
  "use strict";
  var form = document.querySelector("form.search");
  var input = document.getElementById("search");
  if (!form || !input) return;
  var count = document.getElementById("search-count");
  var none = document.getElementById("no-match");
  var items = Array.prototype.slice.call(document.querySelectorAll("ul.entries li[data-name]"));
  var sections = Array.prototype.slice.call(document.querySelectorAll("section.kind"));

  // Every word typed must appear in the name (or its summary).
  function filter() {
    var words = input.value.toLowerCase().split(/\s+/).filter(Boolean);
    var shown = 0;
    items.forEach(function (li) {
      var text = li.getAttribute("data-name") + " " + li.textContent.toLowerCase();
      var match = words.every(function (w) { return text.indexOf(w) !== -1; });
      li.hidden = !match;
      if (match) shown += 1;
    });
    sections.forEach(function (section) {
      section.hidden = !section.querySelector("li[data-name]:not([hidden])");
    });
    count.textContent = words.length ? shown + " of " + items.length : items.length + " entries";
    none.hidden = shown !== 0;
  }

  form.hidden = false;
  // index.html#q=can opens the index filtered.
  var initial = /^#q=(.*)$/.exec(location.hash);
  if (initial) input.value = decodeURIComponent(initial[1]);
  input.addEventListener("input", filter);
  // Enter opens the first match; "/" anywhere focuses the box.
  input.addEventListener("keydown", function (event) {
    if (event.key !== "Enter") return;
    var first = items.filter(function (li) { return !li.hidden; })[0];
    if (first) first.querySelector("a").click();
  });
  document.addEventListener("keydown", function (event) {
    if (event.key === "/" && document.activeElement !== input) {
      event.preventDefault();
      input.focus();
    }
  });
  filter();
})();
