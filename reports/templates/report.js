(function () {
  "use strict";
  var boxes = Array.prototype.slice.call(document.querySelectorAll("input.verdict-filter"));
  var search = document.getElementById("search");
  var rows = Array.prototype.slice.call(document.querySelectorAll("tr.claim"));
  var chapters = Array.prototype.slice.call(document.querySelectorAll(".chapter-claims"));
  var shown = document.getElementById("shown-count");
  var none = document.getElementById("no-matches");
  function apply() {
    var wanted = {};
    boxes.forEach(function (box) { wanted[box.value] = box.checked; });
    var query = search.value.trim().toLowerCase();
    var count = 0;
    rows.forEach(function (row) {
      var visible = wanted[row.dataset.verdict] !== false &&
        (!query || row.dataset.search.indexOf(query) !== -1);
      row.hidden = !visible;
      if (visible) { count += 1; }
    });
    // a chapter with no row left is hidden whole, heading and all
    chapters.forEach(function (chapter) {
      chapter.hidden = !chapter.querySelector("tr.claim:not([hidden])");
    });
    shown.textContent = String(count);
    none.hidden = count !== 0;
  }
  boxes.forEach(function (box) { box.addEventListener("change", apply); });
  search.addEventListener("input", apply);
  apply();
})();
