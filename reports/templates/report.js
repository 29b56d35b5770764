(function () {
  "use strict";
  var boxes = Array.prototype.slice.call(document.querySelectorAll("input.verdict-filter"));
  var search = document.getElementById("search");
  var rows = Array.prototype.slice.call(document.querySelectorAll("tr.claim"));
  var shown = document.getElementById("shown-count");
  function apply() {
    var wanted = {};
    boxes.forEach(function (box) { wanted[box.value] = box.checked; });
    var query = search.value.trim().toLowerCase();
    var count = 0;
    rows.forEach(function (row) {
      var visible = wanted[row.dataset.verdict] !== false &&
        (!query || row.textContent.toLowerCase().indexOf(query) !== -1);
      row.hidden = !visible;
      if (visible) { count += 1; }
    });
    shown.textContent = String(count);
  }
  boxes.forEach(function (box) { box.addEventListener("change", apply); });
  search.addEventListener("input", apply);
  apply();
})();
