// Sorts the table of students by the column whose heading is clicked; a second click reverses.
// Cells sort by their data-sort attribute where they have one (times in milliseconds, shares,
// grades), else by their text. Numeric columns compare as numbers (a cell that is not a number
// sorts first); text compares digits by value ("id 9" before "id 10") and ignores case. Rows
// that compare equal keep their order, so sorting by one column and then another groups by both.
(function () {
  'use strict';
  var table = document.getElementById('students');
  var headers = table.tHead.rows[0].cells;
  var body = table.tBodies[0];
  var collator = new Intl.Collator(undefined, {numeric: true, sensitivity: 'base'});

  function key(row, column, numeric) {
    var cell = row.cells[column];
    var value = cell.hasAttribute('data-sort') ? cell.getAttribute('data-sort') : cell.textContent.trim();
    if (!numeric) {
      return value;
    }
    var number = parseFloat(value);
    return isNaN(number) ? -Infinity : number;
  }

  function compare(a, b, numeric) {
    if (numeric) {
      return a < b ? -1 : a > b ? 1 : 0;
    }
    return collator.compare(a, b);
  }

  function sortBy(column) {
    var header = headers[column];
    var ascending = header.getAttribute('aria-sort') !== 'ascending';
    var numeric = header.getAttribute('data-type') === 'number';
    var rows = Array.prototype.map.call(body.rows, function (row, position) {
      return {row: row, position: position, key: key(row, column, numeric)};
    });
    rows.sort(function (a, b) {
      var order = compare(a.key, b.key, numeric);
      return (ascending ? order : -order) || a.position - b.position;
    });
    Array.prototype.forEach.call(headers, function (other) {
      other.removeAttribute('aria-sort');
    });
    header.setAttribute('aria-sort', ascending ? 'ascending' : 'descending');
    var fragment = document.createDocumentFragment();
    rows.forEach(function (entry) {
      fragment.appendChild(entry.row);
    });
    body.appendChild(fragment);
  }

  Array.prototype.forEach.call(headers, function (header, column) {
    header.addEventListener('click', function () {
      sortBy(column);
    });
  });
  document.body.setAttribute('data-status', 'ready');
})();
