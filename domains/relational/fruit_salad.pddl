; foon2pddl, encoding relational, level 3: 17 of 101 units after relevance pruning
; goal: fruit salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 20 (banana 1, bowl 1, cutting board 3, fruit salad 1, heavy cream 2, honey 2, juicer 1, knife 1, lime 1, lime juice 1, mixing bowl 1, spoon 1, strawberry 1, sugar 1, whipped cream 1, whisk 1)
; objects: 3 x cutting board (empty): FOON's plan, unfolded, takes one out of that state each time it fires pick-and-place at 07-guacamole.foon:52, pick-and-place at 09-fruit_salad.foon:3, pick-and-place at 09-fruit_salad.foon:34, and no unit puts one back
; label mismatch: 09-fruit_salad.foon:199: bowl lists whipped cream, which the unit puts on [fruit salad]
(define (domain foon-relational-da776df9)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    banana - physical-object
    bowl - physical-object
    carton - physical-object
    cutting_board - physical-object
    fruit_salad - physical-object
    heavy_cream - physical-object
    honey - physical-object
    jar - physical-object
    juicer - physical-object
    knife - physical-object
    lime - physical-object
    lime_juice - physical-object
    mixing_bowl - physical-object
    spoon - physical-object
    strawberry - physical-object
    sugar - physical-object
    whipped_cream - physical-object
    whisk - physical-object
  )
  (:constants
    not-yet-made - object-state
    consumed - object-state
    banana_in_bowl_sliced - object-state
    banana_on_cutting_board_peeled - object-state
    banana_on_cutting_board_sliced - object-state
    banana_peeled - object-state
    banana_whole - object-state
    bowl_contains_banana_honey_lime_juice_strawberry - object-state
    bowl_contains_banana_lime_juice_strawberry - object-state
    bowl_contains_banana_strawberry - object-state
    bowl_contains_fruit_salad - object-state
    bowl_contains_fruit_salad_whipped_cream - object-state
    bowl_contains_strawberry - object-state
    bowl_empty - object-state
    carton_contains_heavy_cream - object-state
    cutting_board_contains_banana - object-state
    cutting_board_contains_lime - object-state
    cutting_board_contains_strawberry - object-state
    cutting_board_empty - object-state
    fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl - object-state
    fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d - object-state
    heavy_cream_in_carton - object-state
    heavy_cream_in_mixing_bowl - object-state
    honey_in_bowl - object-state
    honey_in_jar - object-state
    jar_contains_honey - object-state
    juicer_contains_lime_juice - object-state
    juicer_empty - object-state
    knife_plain - object-state
    lime_halved_on_cutting_board - object-state
    lime_on_cutting_board_whole - object-state
    lime_squeezed - object-state
    lime_whole - object-state
    lime_juice_in_bowl - object-state
    lime_juice_in_juicer - object-state
    mixing_bowl_contains_heavy_cream - object-state
    mixing_bowl_contains_heavy_cream_sugar - object-state
    mixing_bowl_contains_whipped_cream - object-state
    mixing_bowl_empty - object-state
    spoon_plain - object-state
    strawberry_in_bowl_sliced - object-state
    strawberry_on_cutting_board_sliced - object-state
    strawberry_on_cutting_board_whole - object-state
    strawberry_whole - object-state
    sugar_granulated - object-state
    sugar_in_mixing_bowl - object-state
    whipped_cream_in_mixing_bowl_whipped - object-state
    whipped_cream_on_fruit_salad_whipped - object-state
    whisk_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (in ?h - physical-object ?x - physical-object)  ; ?x is in ?h
    (on ?h - physical-object ?x - physical-object)  ; ?x is on ?h
    (occupied ?s - object-state)  ; some object is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?heavy_cream_portion - heavy_cream)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_empty)
      (is ?heavy_cream_portion not-yet-made)
      (occupied heavy_cream_in_carton)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?heavy_cream_portion heavy_cream_in_mixing_bowl)
      (in ?mixing_bowl ?heavy_cream_portion)
      (not (is ?mixing_bowl mixing_bowl_empty))
      (not (is ?heavy_cream_portion not-yet-made))
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?sugar - sugar)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?sugar sugar_granulated)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_in_mixing_bowl)
      (in ?mixing_bowl ?sugar)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream))
      (not (is ?sugar sugar_granulated))
    )
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
      (is ?lime_juice lime_juice_in_juicer)
      (in ?juicer ?lime_juice)
      (not (is ?lime lime_halved_on_cutting_board))
      (not (is ?juicer juicer_empty))
      (not (is ?lime_juice not-yet-made))
      (forall (?from_0 - physical-object) (when (on ?from_0 ?lime) (not (on ?from_0 ?lime))))
      (forall (?from_0 - physical-object) (when (and (on ?from_0 ?lime) (is ?from_0 cutting_board_contains_lime)) (and (is ?from_0 cutting_board_empty) (not (is ?from_0 cutting_board_contains_lime)))))
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
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?strawberry) (is ?from_1 cutting_board_contains_strawberry)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_strawberry)))))
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
      (forall (?from_1 - physical-object) (when (and (on ?from_1 ?banana) (is ?from_1 cutting_board_contains_banana)) (and (is ?from_1 cutting_board_empty) (not (is ?from_1 cutting_board_contains_banana)))))
    )
  )

  (:action pour_u96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters (?juicer - juicer ?lime_juice - lime_juice ?bowl - bowl)
    :precondition (and
      (is ?juicer juicer_contains_lime_juice)
      (is ?lime_juice lime_juice_in_juicer)
      (in ?juicer ?lime_juice)
      (is ?bowl bowl_contains_banana_strawberry)
    )
    :effect (and
      (is ?juicer juicer_empty)
      (is ?lime_juice lime_juice_in_bowl)
      (in ?bowl ?lime_juice)
      (is ?bowl bowl_contains_banana_lime_juice_strawberry)
      (not (is ?juicer juicer_contains_lime_juice))
      (not (is ?lime_juice lime_juice_in_juicer))
      (not (in ?juicer ?lime_juice))
      (not (is ?bowl bowl_contains_banana_strawberry))
    )
  )

  (:action pour_u97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters (?bowl - bowl ?honey_portion - honey)
    :precondition (and
      (is ?bowl bowl_contains_banana_lime_juice_strawberry)
      (is ?honey_portion not-yet-made)
      (occupied honey_in_jar)
    )
    :effect (and
      (is ?bowl bowl_contains_banana_honey_lime_juice_strawberry)
      (is ?honey_portion honey_in_bowl)
      (in ?bowl ?honey_portion)
      (not (is ?bowl bowl_contains_banana_lime_juice_strawberry))
      (not (is ?honey_portion not-yet-made))
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
      (is ?strawberry consumed)
      (is ?banana consumed)
      (is ?lime_juice consumed)
      (is ?honey consumed)
      (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
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
      (forall (?strawberry_alike - strawberry) (when (and (in ?bowl ?strawberry_alike) (is ?strawberry_alike strawberry_in_bowl_sliced)) (and (is ?strawberry_alike consumed) (not (in ?bowl ?strawberry_alike)) (not (is ?strawberry_alike strawberry_in_bowl_sliced)))))
      (forall (?banana_alike - banana) (when (and (in ?bowl ?banana_alike) (is ?banana_alike banana_in_bowl_sliced)) (and (is ?banana_alike consumed) (not (in ?bowl ?banana_alike)) (not (is ?banana_alike banana_in_bowl_sliced)))))
      (forall (?lime_juice_alike - lime_juice) (when (and (in ?bowl ?lime_juice_alike) (is ?lime_juice_alike lime_juice_in_bowl)) (and (is ?lime_juice_alike consumed) (not (in ?bowl ?lime_juice_alike)) (not (is ?lime_juice_alike lime_juice_in_bowl)))))
      (forall (?honey_alike - honey) (when (and (in ?bowl ?honey_alike) (is ?honey_alike honey_in_bowl)) (and (is ?honey_alike consumed) (not (in ?bowl ?honey_alike)) (not (is ?honey_alike honey_in_bowl)))))
    )
  )

  (:action whisk_u99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters (?mixing_bowl - mixing_bowl ?heavy_cream - heavy_cream ?sugar - sugar ?whipped_cream - whipped_cream)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (is ?heavy_cream heavy_cream_in_mixing_bowl)
      (in ?mixing_bowl ?heavy_cream)
      (is ?sugar sugar_in_mixing_bowl)
      (in ?mixing_bowl ?sugar)
      (occupied whisk_plain)
      (is ?whipped_cream not-yet-made)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_whipped_cream)
      (is ?heavy_cream consumed)
      (is ?sugar consumed)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (in ?mixing_bowl ?whipped_cream)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar))
      (not (is ?heavy_cream heavy_cream_in_mixing_bowl))
      (not (in ?mixing_bowl ?heavy_cream))
      (not (is ?sugar sugar_in_mixing_bowl))
      (not (in ?mixing_bowl ?sugar))
      (not (is ?whipped_cream not-yet-made))
      (forall (?heavy_cream_alike - heavy_cream) (when (and (in ?mixing_bowl ?heavy_cream_alike) (is ?heavy_cream_alike heavy_cream_in_mixing_bowl)) (and (is ?heavy_cream_alike consumed) (not (in ?mixing_bowl ?heavy_cream_alike)) (not (is ?heavy_cream_alike heavy_cream_in_mixing_bowl)))))
      (forall (?sugar_alike - sugar) (when (and (in ?mixing_bowl ?sugar_alike) (is ?sugar_alike sugar_in_mixing_bowl)) (and (is ?sugar_alike consumed) (not (in ?mixing_bowl ?sugar_alike)) (not (is ?sugar_alike sugar_in_mixing_bowl)))))
    )
  )

  (:action scoop_u100
    ; unit 100: scoop from 09-fruit_salad.foon:199
    ; scoop: bowl (contains {fruit salad}), fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl]), mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spoon -> bowl (contains {fruit salad, whi...
    :parameters (?bowl - bowl ?fruit_salad - fruit_salad ?mixing_bowl - mixing_bowl ?whipped_cream - whipped_cream)
    :precondition (and
      (is ?bowl bowl_contains_fruit_salad)
      (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl)
      (in ?bowl ?fruit_salad)
      (is ?mixing_bowl mixing_bowl_contains_whipped_cream)
      (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped)
      (in ?mixing_bowl ?whipped_cream)
      (occupied spoon_plain)
    )
    :effect (and
      (is ?bowl bowl_contains_fruit_salad_whipped_cream)
      (occupied bowl_contains_fruit_salad_whipped_cream)
      (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
      (occupied fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
      (is ?mixing_bowl mixing_bowl_empty)
      (is ?whipped_cream whipped_cream_on_fruit_salad_whipped)
      (occupied whipped_cream_on_fruit_salad_whipped)
      (on ?fruit_salad ?whipped_cream)
      (not (is ?bowl bowl_contains_fruit_salad))
      (not (is ?fruit_salad fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl))
      (not (is ?mixing_bowl mixing_bowl_contains_whipped_cream))
      (not (is ?whipped_cream whipped_cream_in_mixing_bowl_whipped))
      (not (in ?mixing_bowl ?whipped_cream))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl], topped {whipped cream})
    :parameters ()
    :precondition (and
      (occupied fruit_salad_contains_banana_honey_lime_juice_strawberry_in_bowl_topped__831a7d6d)
    )
    :effect (and
      (goal-reached)
    )
  )
)
