package plcvec

import (
	"reflect"
	"testing"
)

// TestFollowedIsTheMap: Followed names the map that Plan.Choices always was, without making it
// another type: code that spells map[string]Choice assigns to and from it unchanged.
func TestFollowedIsTheMap(t *testing.T) {
	field, ok := reflect.TypeOf(Plan{}).FieldByName("Choices")
	if !ok {
		t.Fatal("Plan has no field Choices")
	}
	want := reflect.TypeOf(map[string]Choice(nil))
	if field.Type != want || reflect.TypeOf(Followed(nil)) != want {
		t.Errorf("Plan.Choices is %v and Followed is %v; want both %v", field.Type, reflect.TypeOf(Followed(nil)), want)
	}
	var spelled map[string]Choice = Followed{"X": {Alternative: "a", Default: "a"}}
	plan := Plan{Choices: spelled}
	if plan.Choices["X"].Alternative != "a" {
		t.Errorf("Plan.Choices from a map[string]Choice: %v", plan.Choices)
	}
}
