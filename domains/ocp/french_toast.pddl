; foon2pddl, encoding ocp, level 3: 5 of 101 units after relevance pruning
; goal: french toast (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-daed508f)
  (:requirements :strips)
  (:constants
    air
    bread
    butter
    french_toast
    frying_pan
    plate
    spatula
    stove
    table
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
    (is-sliced ?o)  ; ?o is sliced
  )

  (:action pick-and-place_frying_pan_22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (in frying_pan air)
      (under frying_pan table)
      (on table frying_pan)
      (under stove table)
      (on table stove)
    )
    :effect (and
      (on stove frying_pan)
      (under frying_pan stove)
      (on table frying_pan)
      (under stove table)
      (on table stove)
      (in frying_pan air)
    )
  )

  (:action pick-and-place_butter_24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (in frying_pan air)
      (on stove frying_pan)
      (under frying_pan stove)
      (under butter table)
      (on table butter)
    )
    :effect (and
      (in frying_pan butter)
      (under butter frying_pan)
      (on table butter)
      (on stove frying_pan)
      (under frying_pan stove)
      (not (in frying_pan air))
    )
  )

  (:action pick-and-place_43
    ; unit 43: pick-and-place from 05-french_toast.foon:121
    ; pick-and-place: frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted), bread (sliced, soaked {custard}) -> frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan butter)
      (under butter frying_pan)
      (is-sliced bread)
      (under bread table)
      (on table bread)
    )
    :effect (and
      (in frying_pan bread)
      (under bread frying_pan)
      (under butter frying_pan)
      (on table bread)
      (on stove frying_pan)
      (under frying_pan stove)
      (is-sliced bread)
    )
  )

  (:action fry_44
    ; unit 44: fry from 05-french_toast.foon:139
    ; fry: stove (on), frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard}), spatula -> frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan bread)
      (under bread frying_pan)
      (is-sliced bread)
      (under spatula table)
      (on table spatula)
    )
    :effect (and
      (in frying_pan french_toast)
      (under french_toast frying_pan)
      (under stove table)
      (under bread frying_pan)
      (is-sliced bread)
      (on stove frying_pan)
      (under frying_pan stove)
      (under spatula table)
      (on table spatula)
    )
  )

  (:action pick-and-place_french_toast_45
    ; unit 45: pick-and-place from 05-french_toast.foon:158
    ; pick-and-place: frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {french toast}), french toast (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan french_toast)
      (under french_toast frying_pan)
      (under spatula table)
      (on table spatula)
      (on plate air)
      (under plate table)
      (on table plate)
    )
    :effect (and
      (on plate french_toast)
      (under french_toast plate)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan french_toast)
      (under plate table)
      (on table plate)
      (under spatula table)
      (on table spatula)
      (not (on plate air))
    )
  )
)
