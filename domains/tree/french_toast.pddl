; foon2pddl, encoding tree, level 3: 15 of 101 units after relevance pruning
; goal: french toast (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-tree-36ae5d94)
  (:requirements :strips)
  (:predicates
    (bowl_contains_cinnamon_egg_milk_vanilla_extract)  ; bowl (contains {cinnamon, egg, milk, vanilla extract})
    (bowl_contains_custard)  ; bowl (contains {custard})
    (bowl_contains_egg)  ; bowl (contains {egg})
    (bowl_contains_egg_milk)  ; bowl (contains {egg, milk})
    (bowl_empty)  ; bowl (empty)
    (bread_in_frying_pan_sliced_soaked_custard)  ; bread (in [frying pan], sliced, soaked {custard})
    (bread_sliced)  ; bread (sliced)
    (bread_sliced_soaked_custard)  ; bread (sliced, soaked {custard})
    (butter_in_frying_pan_melted)  ; butter (in [frying pan], melted)
    (butter_in_frying_pan_solid)  ; butter (in [frying pan], solid)
    (butter_solid)  ; butter (solid)
    (cinnamon_ground)  ; cinnamon (ground)
    (cinnamon_in_bowl)  ; cinnamon (in [bowl])
    (custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)  ; custard (contains {cinnamon, egg, milk, vanilla extract}, in [bowl])
    (egg_beaten_in_bowl)  ; egg (beaten, in [bowl])
    (egg_cracked_in_bowl)  ; egg (cracked, in [bowl])
    (egg_whole)  ; egg (whole)
    (fork)  ; fork
    (french_toast_cooked_in_frying_pan)  ; french toast (cooked, in [frying pan])
    (french_toast_cooked_on_plate)  ; french toast (cooked, on [plate])
    (french_toast_cooked_on_plate_topped_maple_syrup)  ; french toast (cooked, on [plate], topped {maple syrup})
    (frying_pan_contains_bread_butter_on_stove)  ; frying pan (contains {bread, butter}, on [stove])
    (frying_pan_contains_butter_on_stove)  ; frying pan (contains {butter}, on [stove])
    (frying_pan_contains_french_toast_on_stove)  ; frying pan (contains {french toast}, on [stove])
    (frying_pan_empty)  ; frying pan (empty)
    (frying_pan_empty_on_stove)  ; frying pan (empty, on [stove])
    (maple_syrup_in_bottle)  ; maple syrup (in [bottle])
    (maple_syrup_on_french_toast)  ; maple syrup (on [french toast])
    (milk_in_bowl)  ; milk (in [bowl])
    (milk_in_carton)  ; milk (in [carton])
    (plate_contains_french_toast)  ; plate (contains {french toast})
    (plate_contains_french_toast_maple_syrup)  ; plate (contains {french toast, maple syrup})
    (plate_empty)  ; plate (empty)
    (spatula)  ; spatula
    (stove_off)  ; stove (off)
    (stove_on)  ; stove (on)
    (vanilla_extract_in_bowl)  ; vanilla extract (in [bowl])
    (vanilla_extract_liquid)  ; vanilla extract (liquid)
    (whisk)  ; whisk
  )

  (:action crack_u17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (bowl_empty)
      (egg_whole)
    )
    :effect (and
      (bowl_contains_egg)
      (egg_cracked_in_bowl)
    )
  )

  (:action beat_u18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters ()
    :precondition (and
      (egg_cracked_in_bowl)
      (whisk)
    )
    :effect (and
      (egg_beaten_in_bowl)
      (whisk)
    )
  )

  (:action pour_u19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_egg)
      (egg_beaten_in_bowl)
      (milk_in_carton)
    )
    :effect (and
      (bowl_contains_egg_milk)
      (milk_in_bowl)
    )
  )

  (:action pick-and-place_u22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (frying_pan_empty)
      (stove_off)
    )
    :effect (and
      (frying_pan_empty_on_stove)
    )
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (stove_off)
    )
    :effect (and
      (stove_on)
    )
  )

  (:action pick-and-place_u24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (butter_solid)
      (frying_pan_empty_on_stove)
    )
    :effect (and
      (butter_in_frying_pan_solid)
      (frying_pan_contains_butter_on_stove)
    )
  )

  (:action melt_u25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (butter_in_frying_pan_solid)
      (stove_on)
    )
    :effect (and
      (butter_in_frying_pan_melted)
    )
  )

  (:action beat_u39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters ()
    :precondition (and
      (egg_cracked_in_bowl)
      (fork)
    )
    :effect (and
      (egg_beaten_in_bowl)
      (fork)
    )
  )

  (:action pour_u40
    ; unit 40: pour* from 05-french_toast.foon:37
    ; pour: bowl (contains {egg, milk}), cinnamon (ground), vanilla extract (liquid) -> bowl (contains {cinnamon, egg, milk, vanilla extract}), cinnamon (in [bowl]), vanilla extract (in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_egg_milk)
      (cinnamon_ground)
      (vanilla_extract_liquid)
    )
    :effect (and
      (bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (cinnamon_in_bowl)
      (vanilla_extract_in_bowl)
    )
  )

  (:action mix_u41
    ; unit 41: mix from 05-french_toast.foon:51
    ; mix: bowl (contains {cinnamon, egg, milk, vanilla extract}), egg (beaten, in [bowl]), milk (in [bowl]), cinnamon (in [bowl]), vanilla extract (in [bowl]), fork -> bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla...
    :parameters ()
    :precondition (and
      (bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (cinnamon_in_bowl)
      (egg_beaten_in_bowl)
      (fork)
      (milk_in_bowl)
      (vanilla_extract_in_bowl)
    )
    :effect (and
      (bowl_contains_custard)
      (custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
      (fork)
    )
  )

  (:action dip_u42
    ; unit 42: dip from 05-french_toast.foon:71
    ; dip: bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla extract}, in [bowl]), bread (sliced) -> bread (sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (bowl_contains_custard)
      (bread_sliced)
      (custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
    )
    :effect (and
      (bread_sliced_soaked_custard)
    )
  )

  (:action pick-and-place_u43
    ; unit 43: pick-and-place from 05-french_toast.foon:121
    ; pick-and-place: frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted), bread (sliced, soaked {custard}) -> frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (bread_sliced_soaked_custard)
      (butter_in_frying_pan_melted)
      (frying_pan_contains_butter_on_stove)
    )
    :effect (and
      (bread_in_frying_pan_sliced_soaked_custard)
      (frying_pan_contains_bread_butter_on_stove)
    )
  )

  (:action fry_u44
    ; unit 44: fry from 05-french_toast.foon:139
    ; fry: stove (on), frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard}), spatula -> frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (bread_in_frying_pan_sliced_soaked_custard)
      (frying_pan_contains_bread_butter_on_stove)
      (spatula)
      (stove_on)
    )
    :effect (and
      (french_toast_cooked_in_frying_pan)
      (frying_pan_contains_french_toast_on_stove)
      (spatula)
    )
  )

  (:action pick-and-place_u45
    ; unit 45: pick-and-place from 05-french_toast.foon:158
    ; pick-and-place: frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {french toast}), french toast (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (french_toast_cooked_in_frying_pan)
      (frying_pan_contains_french_toast_on_stove)
      (plate_empty)
      (spatula)
    )
    :effect (and
      (french_toast_cooked_on_plate)
      (plate_contains_french_toast)
      (spatula)
    )
  )

  (:action pour_u46
    ; unit 46: pour from 05-french_toast.foon:175
    ; pour: plate (contains {french toast}), french toast (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {french toast, maple syrup}), french toast (cooked, on [plate], topped {maple syrup}), maple syrup (on [french toast])
    :parameters ()
    :precondition (and
      (french_toast_cooked_on_plate)
      (maple_syrup_in_bottle)
      (plate_contains_french_toast)
    )
    :effect (and
      (french_toast_cooked_on_plate_topped_maple_syrup)
      (maple_syrup_on_french_toast)
      (plate_contains_french_toast_maple_syrup)
    )
  )
)
