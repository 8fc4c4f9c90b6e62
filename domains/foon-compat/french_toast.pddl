; foon2pddl, encoding foon-compat, level 3: 15 of 101 units after relevance pruning
; goal: french toast (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain universal_foon-159f1fed)
  (:requirements :strips :typing)
  (:types
    object_node - object
  )
  (:constants
    bowl_contains_cinnamon_egg_milk_vanilla_extract - object_node
    bowl_contains_custard - object_node
    bowl_contains_egg - object_node
    bowl_contains_egg_milk - object_node
    bowl_empty - object_node
    bread_in_frying_pan_sliced_soaked_custard - object_node
    bread_sliced - object_node
    bread_sliced_soaked_custard - object_node
    butter_in_frying_pan_melted - object_node
    butter_in_frying_pan_solid - object_node
    butter_solid - object_node
    cinnamon_ground - object_node
    cinnamon_in_bowl - object_node
    custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl - object_node
    egg_beaten_in_bowl - object_node
    egg_cracked_in_bowl - object_node
    egg_whole - object_node
    fork - object_node
    french_toast_cooked_in_frying_pan - object_node
    french_toast_cooked_on_plate - object_node
    french_toast_cooked_on_plate_topped_maple_syrup - object_node
    frying_pan_contains_bread_butter_on_stove - object_node
    frying_pan_contains_butter_on_stove - object_node
    frying_pan_contains_french_toast_on_stove - object_node
    frying_pan_empty - object_node
    frying_pan_empty_on_stove - object_node
    maple_syrup_in_bottle - object_node
    maple_syrup_on_french_toast - object_node
    milk_in_bowl - object_node
    milk_in_carton - object_node
    plate_contains_french_toast - object_node
    plate_contains_french_toast_maple_syrup - object_node
    plate_empty - object_node
    spatula - object_node
    stove_off - object_node
    stove_on - object_node
    vanilla_extract_in_bowl - object_node
    vanilla_extract_liquid - object_node
    whisk - object_node
  )
  (:predicates
    (is_available ?obj - object_node)  ; the object node is available
  )

  (:action functional_unit_17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_empty)
      (is_available egg_whole)
    )
    :effect (and
      (is_available bowl_contains_egg)
      (is_available egg_cracked_in_bowl)
    )
  )

  (:action functional_unit_18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters ()
    :precondition (and
      (is_available egg_cracked_in_bowl)
      (is_available whisk)
    )
    :effect (and
      (is_available egg_beaten_in_bowl)
      (is_available whisk)
    )
  )

  (:action functional_unit_19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_egg)
      (is_available egg_beaten_in_bowl)
      (is_available milk_in_carton)
    )
    :effect (and
      (is_available bowl_contains_egg_milk)
      (is_available milk_in_bowl)
    )
  )

  (:action functional_unit_22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (is_available frying_pan_empty)
      (is_available stove_off)
    )
    :effect (and
      (is_available frying_pan_empty_on_stove)
    )
  )

  (:action functional_unit_23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (is_available stove_off)
    )
    :effect (and
      (is_available stove_on)
    )
  )

  (:action functional_unit_24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (is_available butter_solid)
      (is_available frying_pan_empty_on_stove)
    )
    :effect (and
      (is_available butter_in_frying_pan_solid)
      (is_available frying_pan_contains_butter_on_stove)
    )
  )

  (:action functional_unit_25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (is_available butter_in_frying_pan_solid)
      (is_available stove_on)
    )
    :effect (and
      (is_available butter_in_frying_pan_melted)
    )
  )

  (:action functional_unit_39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters ()
    :precondition (and
      (is_available egg_cracked_in_bowl)
      (is_available fork)
    )
    :effect (and
      (is_available egg_beaten_in_bowl)
      (is_available fork)
    )
  )

  (:action functional_unit_40
    ; unit 40: pour* from 05-french_toast.foon:37
    ; pour: bowl (contains {egg, milk}), cinnamon (ground), vanilla extract (liquid) -> bowl (contains {cinnamon, egg, milk, vanilla extract}), cinnamon (in [bowl]), vanilla extract (in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_egg_milk)
      (is_available cinnamon_ground)
      (is_available vanilla_extract_liquid)
    )
    :effect (and
      (is_available bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (is_available cinnamon_in_bowl)
      (is_available vanilla_extract_in_bowl)
    )
  )

  (:action functional_unit_41
    ; unit 41: mix from 05-french_toast.foon:51
    ; mix: bowl (contains {cinnamon, egg, milk, vanilla extract}), egg (beaten, in [bowl]), milk (in [bowl]), cinnamon (in [bowl]), vanilla extract (in [bowl]), fork -> bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla...
    :parameters ()
    :precondition (and
      (is_available bowl_contains_cinnamon_egg_milk_vanilla_extract)
      (is_available cinnamon_in_bowl)
      (is_available egg_beaten_in_bowl)
      (is_available fork)
      (is_available milk_in_bowl)
      (is_available vanilla_extract_in_bowl)
    )
    :effect (and
      (is_available bowl_contains_custard)
      (is_available custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
      (is_available fork)
    )
  )

  (:action functional_unit_42
    ; unit 42: dip from 05-french_toast.foon:71
    ; dip: bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla extract}, in [bowl]), bread (sliced) -> bread (sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (is_available bowl_contains_custard)
      (is_available bread_sliced)
      (is_available custard_contains_cinnamon_egg_milk_vanilla_extract_in_bowl)
    )
    :effect (and
      (is_available bread_sliced_soaked_custard)
    )
  )

  (:action functional_unit_43
    ; unit 43: pick-and-place from 05-french_toast.foon:121
    ; pick-and-place: frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted), bread (sliced, soaked {custard}) -> frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (is_available bread_sliced_soaked_custard)
      (is_available butter_in_frying_pan_melted)
      (is_available frying_pan_contains_butter_on_stove)
    )
    :effect (and
      (is_available bread_in_frying_pan_sliced_soaked_custard)
      (is_available frying_pan_contains_bread_butter_on_stove)
    )
  )

  (:action functional_unit_44
    ; unit 44: fry from 05-french_toast.foon:139
    ; fry: stove (on), frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard}), spatula -> frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (is_available bread_in_frying_pan_sliced_soaked_custard)
      (is_available frying_pan_contains_bread_butter_on_stove)
      (is_available spatula)
      (is_available stove_on)
    )
    :effect (and
      (is_available french_toast_cooked_in_frying_pan)
      (is_available frying_pan_contains_french_toast_on_stove)
      (is_available spatula)
    )
  )

  (:action functional_unit_45
    ; unit 45: pick-and-place from 05-french_toast.foon:158
    ; pick-and-place: frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {french toast}), french toast (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (is_available french_toast_cooked_in_frying_pan)
      (is_available frying_pan_contains_french_toast_on_stove)
      (is_available plate_empty)
      (is_available spatula)
    )
    :effect (and
      (is_available french_toast_cooked_on_plate)
      (is_available plate_contains_french_toast)
      (is_available spatula)
    )
  )

  (:action functional_unit_46
    ; unit 46: pour from 05-french_toast.foon:175
    ; pour: plate (contains {french toast}), french toast (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {french toast, maple syrup}), french toast (cooked, on [plate], topped {maple syrup}), maple syrup (on [french toast])
    :parameters ()
    :precondition (and
      (is_available french_toast_cooked_on_plate)
      (is_available maple_syrup_in_bottle)
      (is_available plate_contains_french_toast)
    )
    :effect (and
      (is_available french_toast_cooked_on_plate_topped_maple_syrup)
      (is_available maple_syrup_on_french_toast)
      (is_available plate_contains_french_toast_maple_syrup)
    )
  )
)
