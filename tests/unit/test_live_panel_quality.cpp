// The viewer panel's [quality] widgets come from the loader's own list
// (scene/quality_fields.h): every key has one, and no widget can set a
// value the loader would refuse.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "live/panel.h"
#include "scene/quality_fields.h"

namespace ms::live {
namespace {

TEST(PanelQuality, EveryKeyHasAWidgetInsideItsRange) {
  int widgets = 0;
  for (const Field<Quality>& f : kQualityFields) {
    const QualityWidget w = quality_widget(f);
    ++widgets;
    if (std::holds_alternative<bool Quality::*>(f.member)) {
      EXPECT_EQ(w.kind, QualityWidget::checkbox) << f.key;
      continue;
    }
    EXPECT_NE(w.kind, QualityWidget::checkbox) << f.key;
    EXPECT_EQ(w.integer, std::holds_alternative<int Quality::*>(f.member)) << f.key;
    EXPECT_TRUE(f.range.contains(w.lo)) << f.key << " lo " << w.lo << ", range " << f.range.describe();
    EXPECT_LE(w.lo, w.hi) << f.key;
    if (w.kind == QualityWidget::slider)
      EXPECT_TRUE(f.range.contains(w.hi)) << f.key << " hi " << w.hi << ", range " << f.range.describe();
  }
  EXPECT_EQ(widgets, static_cast<int>(std::size(kQualityFields)));
}

TEST(PanelQuality, ClosedRangesSlideAndOpenEndsStayInside) {
  for (const Field<Quality>& f : kQualityFields) {
    const QualityWidget w = quality_widget(f);
    if (f.key == "max_steps") {  // [1, 100000]: a slider, logarithmic over five decades
      EXPECT_EQ(w.kind, QualityWidget::slider);
      EXPECT_TRUE(w.log);
      EXPECT_EQ(w.hi, 100000.0);
    }
    if (f.key == "omega") {  // [1, 2): 2 itself is refused
      EXPECT_EQ(w.kind, QualityWidget::slider);
      EXPECT_EQ(w.lo, 1.0);
      EXPECT_LT(w.hi, 2.0);
    }
    if (f.key == "max_distance") {  // > 0, unbounded: a drag from just above 0
      EXPECT_EQ(w.kind, QualityWidget::drag);
      EXPECT_GT(w.lo, 0.0);
    }
  }
}

}  // namespace
}  // namespace ms::live
