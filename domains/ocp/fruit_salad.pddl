; foon2pddl, encoding ocp, level 3: 14 of 101 units after relevance pruning
; goal: fruit salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-c1320020)
  (:requirements :strips)
  (:constants
    air
    avocado
    banana
    bowl
    cutting_board
    fruit_salad
    honey
    jar
    juicer
    knife
    lime
    lime_juice
    spoon
    strawberry
    table
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
    (is-sliced ?o)  ; ?o is sliced
    (is-whole ?o)  ; ?o is whole
  )

  (:action pick-and-place_avocado_63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole avocado)
      (under avocado table)
      (on table avocado)
    )
    :effect (and
      (on cutting_board avocado)
      (under avocado cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole avocado)
      (not (on cutting_board air))
    )
  )

  (:action scoop_avocado_65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (on cutting_board avocado)
      (under avocado cutting_board)
      (under spoon table)
      (on table spoon)
      (in bowl air)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl avocado)
      (under avocado bowl)
      (on cutting_board avocado)
      (under spoon table)
      (on table spoon)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )

  (:action pick-and-place_lime_67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole lime)
      (under lime table)
      (on table lime)
    )
    :effect (and
      (on cutting_board lime)
      (under lime cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole lime)
      (not (on cutting_board air))
    )
  )

  (:action squeeze_69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (on cutting_board lime)
      (under lime cutting_board)
      (in juicer air)
      (under juicer table)
      (on table juicer)
    )
    :effect (and
      (under lime table)
      (on table lime)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (on cutting_board lime)
      (under juicer table)
      (on table juicer)
      (not (in juicer air))
    )
  )

  (:action pour_lime_juice_70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (under juicer table)
      (on table juicer)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (under bowl table)
      (on table bowl)
      (in bowl avocado)
      (under avocado bowl)
    )
    :effect (and
      (in bowl lime_juice)
      (under lime_juice bowl)
      (under juicer table)
      (in juicer lime_juice)
      (under avocado bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action pick-and-place_strawberry_89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole strawberry)
      (under strawberry table)
      (on table strawberry)
    )
    :effect (and
      (on cutting_board strawberry)
      (under strawberry cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole strawberry)
      (not (on cutting_board air))
    )
  )

  (:action slice_strawberry_90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board strawberry)
      (under strawberry cutting_board)
      (is-whole strawberry)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-sliced strawberry)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board strawberry)
      (under strawberry cutting_board)
      (under knife table)
      (on table knife)
      (not (is-whole strawberry))
    )
  )

  (:action pick-and-place_banana_92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (under banana table)
      (on table banana)
    )
    :effect (and
      (on cutting_board banana)
      (under banana cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (not (on cutting_board air))
    )
  )

  (:action slice_banana_93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board banana)
      (under banana cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-sliced banana)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board banana)
      (under banana cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_strawberry_94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (in bowl air)
      (under bowl table)
      (on table bowl)
      (on cutting_board strawberry)
      (under strawberry cutting_board)
      (is-sliced strawberry)
    )
    :effect (and
      (in bowl strawberry)
      (under strawberry bowl)
      (on cutting_board strawberry)
      (under bowl table)
      (on table bowl)
      (is-sliced strawberry)
      (not (in bowl air))
    )
  )

  (:action pick-and-place_banana_95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (on cutting_board banana)
      (under banana cutting_board)
      (is-sliced banana)
    )
    :effect (and
      (in bowl banana)
      (under banana bowl)
      (on cutting_board banana)
      (under bowl table)
      (on table bowl)
      (is-sliced banana)
    )
  )

  (:action pour_lime_juice_96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (under juicer table)
      (on table juicer)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl lime_juice)
      (under lime_juice bowl)
      (under juicer table)
      (in juicer lime_juice)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action pour_honey_97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in jar honey)
      (under honey jar)
    )
    :effect (and
      (in bowl honey)
      (under honey bowl)
      (in jar honey)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action mix_ingredients_98
    ; unit 98: mix from 09-fruit_salad.foon:143
    ; mix: bowl (contains {banana, honey, lime juice, strawberry}), strawberry (in [bowl], sliced), banana (in [bowl], sliced), lime juice (in [bowl]), honey (in [bowl]), spoon -> bowl (contains {fruit salad}), fruit salad (contains {banana, h...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl strawberry)
      (under strawberry bowl)
      (is-sliced strawberry)
      (in bowl banana)
      (under banana bowl)
      (is-sliced banana)
      (in bowl lime_juice)
      (under lime_juice bowl)
      (in bowl honey)
      (under honey bowl)
      (under spoon table)
      (on table spoon)
    )
    :effect (and
      (in bowl fruit_salad)
      (under fruit_salad bowl)
      (under strawberry bowl)
      (is-sliced strawberry)
      (under banana bowl)
      (is-sliced banana)
      (under lime_juice bowl)
      (under honey bowl)
      (under bowl table)
      (on table bowl)
      (under spoon table)
      (on table spoon)
    )
  )
)
