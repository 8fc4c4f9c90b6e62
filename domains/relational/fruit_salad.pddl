; foon2pddl, encoding relational, level 3: 13 of 101 units after relevance pruning
; goal: fruit salad (2 candidate nodes)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 13 (banana 1, bowl 1, cutting board 3, fruit salad 1, honey 1, juicer 1, knife 1, lime 1, lime juice 1, spoon 1, strawberry 1)
(define (domain foon-relational)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    banana - physical-object
    bowl - physical-object
    cutting_board - physical-object
    fruit_salad - physical-object
    honey - physical-object
    juicer - physical-object
    knife - physical-object
    lime - physical-object
    lime_juice - physical-object
    spoon - physical-object
    strawberry - physical-object
    jar - physical-object
  )
  (:constants
    not-yet-made - object-state
    banana_in_bowl_sliced - object-state
    banana_in_fruit_salad_sliced - object-state
    banana_on_cutting_board_peeled - object-state
    banana_on_cutting_board_sliced - object-state
    banana_peeled - object-state
    banana_whole - object-state
    bowl_contains_banana_honey_lime_juice_strawberry - object-state
    bowl_contains_banana_lime_juice_strawberry - object-state
    bowl_contains_banana_strawberry - object-state
    bowl_contains_fruit_salad - object-state
    bowl_contains_strawberry - object-state
    bowl_empty - object-state
    cutting_board_contains_banana - object-state
    cutting_board_contains_lime - object-state
    cutting_board_contains_strawberry - object-state
    cutting_board_empty - object-state
    fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl - object-state
    fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped_whipped_c - object-state
    honey_in_bowl - object-state
    honey_in_fruit_salad - object-state
    honey_in_jar - object-state
    juicer_contains_lime_juice - object-state
    juicer_empty - object-state
    knife_plain - object-state
    lime_halved_on_cutting_board - object-state
    lime_on_cutting_board_whole - object-state
    lime_squeezed - object-state
    lime_whole - object-state
    lime_juice_in_bowl - object-state
    lime_juice_in_fruit_salad - object-state
    lime_juice_in_juicer - object-state
    spoon_plain - object-state
    strawberry_in_bowl_sliced - object-state
    strawberry_in_fruit_salad_sliced - object-state
    strawberry_on_cutting_board_sliced - object-state
    strawberry_on_cutting_board_whole - object-state
    strawberry_whole - object-state
    jar_contains_honey - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (in ?h - physical-object ?x - physical-object)  ; ?x is in ?h
    (on ?h - physical-object ?x - physical-object)  ; ?x is on ?h
    (occupied ?s - object-state)  ; some object is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?lime - lime)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?lime lime_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_lime)
      (occupied cutting_board_contains_lime)
      (is ?lime lime_on_cutting_board_whole)
      (on ?cutting_board ?lime)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?lime lime_whole))
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters (?cutting_board - cutting_board ?lime - lime)
    :precondition (and
      (is ?cutting_board cutting_board_contains_lime)
      (is ?lime lime_on_cutting_board_whole)
      (on ?cutting_board ?lime)
      (occupied knife_plain)
    )
    :effect (and
      (is ?lime lime_halved_on_cutting_board)
      (not (is ?lime lime_on_cutting_board_whole))
    )
  )

  (:action squeeze_u69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters (?lime - lime ?juicer - juicer ?lime_juice - lime_juice)
    :precondition (and
      (is ?lime lime_halved_on_cutting_board)
      (is ?juicer juicer_empty)
      (is ?lime_juice not-yet-made)
    )
    :effect (and
      (is ?lime lime_squeezed)
      (occupied lime_squeezed)
      (is ?juicer juicer_contains_lime_juice)
      (occupied juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (in ?juicer ?lime_juice)
      (not (is ?lime lime_halved_on_cutting_board))
      (not (is ?juicer juicer_empty))
      (not (is ?lime_juice not-yet-made))
      (forall (?from_0 - physical-object) (when (on ?from_0 ?lime) (not (on ?from_0 ?lime))))
    )
  )

  (:action pick-and-place_u89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters (?cutting_board - cutting_board ?strawberry - strawberry)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?strawberry strawberry_whole)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_strawberry)
      (occupied cutting_board_contains_strawberry)
      (is ?strawberry strawberry_on_cutting_board_whole)
      (on ?cutting_board ?strawberry)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?strawberry strawberry_whole))
    )
  )

  (:action slice_u90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters (?cutting_board - cutting_board ?strawberry - strawberry)
    :precondition (and
      (is ?cutting_board cutting_board_contains_strawberry)
      (is ?strawberry strawberry_on_cutting_board_whole)
      (on ?cutting_board ?strawberry)
      (occupied knife_plain)
    )
    :effect (and
      (is ?strawberry strawberry_on_cutting_board_sliced)
      (not (is ?strawberry strawberry_on_cutting_board_whole))
    )
  )

  (:action peel_u91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters (?banana - banana)
    :precondition (and
      (is ?banana banana_whole)
    )
    :effect (and
      (is ?banana banana_peeled)
      (not (is ?banana banana_whole))
    )
  )

  (:action pick-and-place_u92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters (?cutting_board - cutting_board ?banana - banana)
    :precondition (and
      (is ?cutting_board cutting_board_empty)
      (is ?banana banana_peeled)
    )
    :effect (and
      (is ?cutting_board cutting_board_contains_banana)
      (occupied cutting_board_contains_banana)
      (is ?banana banana_on_cutting_board_peeled)
      (on ?cutting_board ?banana)
      (not (is ?cutting_board cutting_board_empty))
      (not (is ?banana banana_peeled))
    )
  )

  (:action slice_u93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters (?cutting_board - cutting_board ?banana - banana)
    :precondition (and
      (is ?cutting_board cutting_board_contains_banana)
      (is ?banana banana_on_cutting_board_peeled)
      (on ?cutting_board ?banana)
      (occupied knife_plain)
    )
    :effect (and
      (is ?banana banana_on_cutting_board_sliced)
      (not (is ?banana banana_on_cutting_board_peeled))
    )
  )

  (:action pick-and-place_u94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters (?bowl - bowl ?strawberry - strawberry)
    :precondition (and
      (is ?bowl bowl_empty)
      (is ?strawberry strawberry_on_cutting_board_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_strawberry)
      (is ?strawberry strawberry_in_bowl_sliced)
      (in ?bowl ?strawberry)
      (not (is ?bowl bowl_empty))
      (not (is ?strawberry strawberry_on_cutting_board_sliced))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?strawberry) (not (on ?from_1 ?strawberry))))
    )
  )

  (:action pick-and-place_u95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters (?bowl - bowl ?banana - banana)
    :precondition (and
      (is ?bowl bowl_contains_strawberry)
      (is ?banana banana_on_cutting_board_sliced)
    )
    :effect (and
      (is ?bowl bowl_contains_banana_strawberry)
      (is ?banana banana_in_bowl_sliced)
      (in ?bowl ?banana)
      (not (is ?bowl bowl_contains_strawberry))
      (not (is ?banana banana_on_cutting_board_sliced))
      (forall (?from_1 - physical-object) (when (on ?from_1 ?banana) (not (on ?from_1 ?banana))))
    )
  )

  (:action pour_u96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters (?lime_juice - lime_juice ?bowl - bowl)
    :precondition (and
      (occupied juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (is ?bowl bowl_contains_banana_strawberry)
    )
    :effect (and
      (is ?lime_juice lime_juice_in_bowl)
      (in ?bowl ?lime_juice)
      (is ?bowl bowl_contains_banana_lime_juice_strawberry)
      (not (is ?lime_juice lime_juice_in_juicer))
      (not (is ?bowl bowl_contains_banana_strawberry))
      (forall (?from_1 - physical-object) (when (in ?from_1 ?lime_juice) (not (in ?from_1 ?lime_juice))))
    )
  )

  (:action pour_u97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters (?bowl - bowl ?honey - honey)
    :precondition (and
      (is ?bowl bowl_contains_banana_lime_juice_strawberry)
      (is ?honey honey_in_jar)
    )
    :effect (and
      (is ?bowl bowl_contains_banana_honey_lime_juice_strawberry)
      (is ?honey honey_in_bowl)
      (in ?bowl ?honey)
      (not (is ?bowl bowl_contains_banana_lime_juice_strawberry))
      (not (is ?honey honey_in_jar))
      (forall (?from_1 - physical-object) (when (in ?from_1 ?honey) (not (in ?from_1 ?honey))))
    )
  )

  (:action mix_u98
    ; unit 98: mix from 09-fruit_salad.foon:143
    ; mix: bowl (contains {banana, honey, lime juice, strawberry}), strawberry (in [bowl], sliced), banana (in [bowl], sliced), lime juice (in [bowl]), honey (in [bowl]), spoon -> bowl (contains {fruit salad}), fruit salad (contains {banana, h...
    :parameters (?bowl - bowl ?strawberry - strawberry ?banana - banana ?lime_juice - lime_juice ?honey - honey ?fruit_salad - fruit_salad)
    :precondition (and
      (is ?bowl bowl_contains_banana_honey_lime_juice_strawberry)
      (is ?strawberry strawberry_in_bowl_sliced)
      (in ?bowl ?strawberry)
      (is ?banana banana_in_bowl_sliced)
      (in ?bowl ?banana)
      (is ?lime_juice lime_juice_in_bowl)
      (in ?bowl ?lime_juice)
      (is ?honey honey_in_bowl)
      (in ?bowl ?honey)
      (occupied spoon_plain)
      (is ?fruit_salad not-yet-made)
    )
    :effect (and
      (is ?bowl bowl_contains_fruit_salad)
      (occupied bowl_contains_fruit_salad)
      (is ?strawberry strawberry_in_fruit_salad_sliced)
      (occupied strawberry_in_fruit_salad_sliced)
      (in ?fruit_salad ?strawberry)
      (is ?banana banana_in_fruit_salad_sliced)
      (occupied banana_in_fruit_salad_sliced)
      (in ?fruit_salad ?banana)
      (is ?lime_juice lime_juice_in_fruit_salad)
      (occupied lime_juice_in_fruit_salad)
      (in ?fruit_salad ?lime_juice)
      (is ?honey honey_in_fruit_salad)
      (occupied honey_in_fruit_salad)
      (in ?fruit_salad ?honey)
      (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (occupied fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (in ?bowl ?fruit_salad)
      (not (is ?bowl bowl_contains_banana_honey_lime_juice_strawberry))
      (not (is ?strawberry strawberry_in_bowl_sliced))
      (not (in ?bowl ?strawberry))
      (not (is ?banana banana_in_bowl_sliced))
      (not (in ?bowl ?banana))
      (not (is ?lime_juice lime_juice_in_bowl))
      (not (in ?bowl ?lime_juice))
      (not (is ?honey honey_in_bowl))
      (not (in ?bowl ?honey))
      (not (is ?fruit_salad not-yet-made))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl])
    :parameters ()
    :precondition (and
      (occupied fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
    )
    :effect (and
      (goal-reached)
    )
  )

  (:action reach-goal-2
    ; goal candidate 2: fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl], topped {whipped cream})
    :parameters ()
    :precondition (and
      (occupied fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped_whipped_c)
    )
    :effect (and
      (goal-reached)
    )
  )
)
